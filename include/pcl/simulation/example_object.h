/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_mesh.h>

#include <cstdint>

namespace pcl
{
  /** \brief Parameters of the built-in example object. */
  struct ExampleObjectParams
  {
    /** Seed of the bumps' random placement (std::mt19937). */
    std::uint32_t seed = 2006;
    /** Icosahedron subdivisions: 20 * 4^k faces (k = 6: 81,920 faces). */
    int subdivisions = 6;
    /** Approximate size of the object along its longest axis, in metres. */
    double size = 0.2;
    /** Number of Gaussian bumps and dents on the ellipsoid. */
    int bumps = 14;
  };

  /** \brief A closed, free-form, asymmetric surface: an ellipsoid with seeded Gaussian bumps and
    * concavities, meshed from a subdivided icosahedron. Normals point outward. It lets the demo and
    * the tests run on data the project makes itself.
    * \ingroup simulation
    */
  ScanMesh
  makeExampleObject (const ExampleObjectParams& params = {});
}
