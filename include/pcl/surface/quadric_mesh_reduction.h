/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_mesh.h>

namespace pcl
{
  /** \brief Garland–Heckbert quadric error simplification of M_i to M'_i (Sections 2 and 3).
    *
    * Uses meshoptimizer's meshopt_simplify, a maintained implementation of the quadric error metric:
    * plane quadrics of the faces, plus constraint quadrics along boundary edges so that the scan's
    * outline is preserved. Each edge collapses onto one of its end points (Garland and Heckbert's
    * "subset placement"), so every vertex of M'_i is a vertex of M_i. VTK's vtkQuadricDecimation
    * (pcl::MeshQuadricDecimationVTK) is much slower and moves vertices off the scan; see
    * doc/design.md#garland-heckbert-reduction-by-meshoptimizer.
    *
    * The paper reduces every view to about 400 faces (Section 7.2), the default here; registration
    * reduces to more (doc/design.md#more-faces-for-registration).
    * \ingroup surface
    */
  class QuadricMeshReduction
  {
    public:
      /** \brief Set the number of faces to reduce to (default 400). */
      void setTargetFaces (int faces);
      int getTargetFaces () const { return target_faces_; }

      /** \brief Drop connected components with fewer than this fraction of the faces before reducing
        * (default 0.01). Edge pruning cuts small fragments off a scan; each would keep faces of the
        * budget while adding nothing that tensors can describe. 0 keeps every component.
        * \note Beyond the paper, which reduces the whole mesh; see
        * doc/design.md#garland-heckbert-reduction-by-meshoptimizer.
        */
      void setMinComponentFraction (double fraction);
      double getMinComponentFraction () const { return min_component_fraction_; }

      /** \brief Reduce \a fine into \a reduced. Normals of \a reduced are zero; its viewpoint is copied.
        * Meshes already at or under the target keep
        * their faces. Either way the output has no isolated vertex, no zero-area and no duplicated triangle.
        * \throw InvalidScanException when \a fine has no faces
        */
      void reduce (const ScanMesh& fine, ScanMesh& reduced) const;

    private:
      int target_faces_{400};
      double min_component_fraction_{0.01};
  };
}
