/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_mesh.h>

namespace pcl
{
  /** \brief Garland–Heckbert quadric error simplification of M_i to M'_i (Sections 2 and 3).
    *
    * Wraps VTK's vtkQuadricDecimation, which adds boundary-constraint quadrics so that the scan's
    * outline is preserved. The paper reduces every view to about 400 faces (Section 7.2).
    * \ingroup surface
    */
  class QuadricMeshReduction
  {
    public:
      /** \brief Set the number of faces to reduce to (default 400). */
      void setTargetFaces (int faces);
      int getTargetFaces () const { return target_faces_; }

      /** \brief Reduce \a fine into \a reduced. Normals of \a reduced are zero; its viewpoint is copied.
        * Meshes already at or under the target are copied unchanged.
        * \throw InvalidScanException when \a fine has no faces
        */
      void reduce (const ScanMesh& fine, ScanMesh& reduced) const;

    private:
      int target_faces_{400};
  };
}
