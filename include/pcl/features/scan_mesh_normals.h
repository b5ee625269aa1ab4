/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_mesh.h>

namespace pcl
{
  /** \brief Vertex normals of a reduced mesh M'_i by either approach of Section 2, oriented toward
    * the sensor.
    * \ingroup features
    */
  class ScanMeshNormalEstimation
  {
    public:
      enum class Method
      {
        /** (a) Area-weighted average of the normals of the faces around the vertex in M'_i. Fast. */
        FACE_AVERAGE,
        /** (b) The normal of the nearest vertex of M_i, averaged (area-weighted) over the faces of
          * M_i within a radius of it. More stable; the default. Where that neighbourhood has no face
          * (an isolated fine vertex), the vertex keeps approach (a). */
        FINE_NEIGHBOURHOOD
      };

      void setMethod (Method method) { method_ = method; }
      Method getMethod () const { return method_; }

      /** \brief Neighbourhood radius for Method::FINE_NEIGHBOURHOOD, in units of the fine mesh's
        * resolution d_res (default 3).
        */
      void setRadiusResolutions (double radius);
      double getRadiusResolutions () const { return radius_resolutions_; }

      /** \brief Fill in the normals of \a mesh from its own faces (Method::FACE_AVERAGE). Vertices on
        * no face (edge pruning can isolate them) get a NaN normal: there is no surface to take it from
        * (doc/design.md#nan-normals-on-isolated-vertices).
        */
      void computeFaceAverage (ScanMesh& mesh) const;

      /** \brief Fill in the normals of \a reduced with the configured method, and those of \a fine by
        * face average with either method (Method::FINE_NEIGHBOURHOOD reads them; point-to-plane
        * verification needs them).
        * \param[in,out] reduced M'_i
        * \param[in,out] fine M_i
        * \param[in] resolution d_res of \a fine if the caller already has it (meshResolution()); 0 computes it
        * \throw InvalidScanException when a mesh has no faces
        */
      void compute (ScanMesh& reduced, ScanMesh& fine, double resolution = 0.0) const;

    private:
      Method method_{Method::FINE_NEIGHBOURHOOD};
      double radius_resolutions_{3.0};
  };
}
