/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/features/scan_mesh_normals.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/search/bounded_nearest_search.h>

#include <limits>

namespace pcl
{
  namespace
  {
    /** Per vertex, the sum of the cross products of its faces: twice the area-weighted normal. */
    std::vector<Eigen::Vector3d>
    areaWeightedSums (const ScanMesh& mesh)
    {
      std::vector<Eigen::Vector3d> sums (mesh.cloud->size (), Eigen::Vector3d::Zero ());
      for (const auto& poly : mesh.polygons)
      {
        const auto& v = poly.vertices;
        const Eigen::Vector3d a = (*mesh.cloud)[v[0]].getVector3fMap ().cast<double> ();
        const Eigen::Vector3d b = (*mesh.cloud)[v[1]].getVector3fMap ().cast<double> ();
        const Eigen::Vector3d c = (*mesh.cloud)[v[2]].getVector3fMap ().cast<double> ();
        const Eigen::Vector3d n = (b - a).cross (c - a);
        for (const auto i : v)
          sums[i] += n;
      }
      return sums;
    }

    /** Normalise and flip toward the sensor. A vertex on no face has no normal to give: it gets
      * NaN, so that consumers (point-to-plane ICP) skip it rather than trust a made-up direction. */
    void
    storeOriented (ScanMesh& mesh, const std::vector<Eigen::Vector3d>& sums)
    {
      const float nan = std::numeric_limits<float>::quiet_NaN ();
      for (std::size_t i = 0; i < sums.size (); ++i)
      {
        auto& p = (*mesh.cloud)[i];
        if (!(sums[i].norm () > 0.0))
        {
          p.normal_x = p.normal_y = p.normal_z = nan;
          continue;
        }
        const Eigen::Vector3d toward = mesh.viewpoint.towardSensor (p.getVector3fMap ().cast<double> ());
        Eigen::Vector3d n = sums[i].normalized ();
        if (n.dot (toward) < 0.0)
          n = -n;
        p.getNormalVector3fMap () = n.cast<float> ();
      }
    }

    void
    requireFaces (const ScanMesh& mesh, const char* which)
    {
      if (mesh.polygons.empty ())
        PCL_TENSOR_THROW (InvalidScanException, "vertex normals need faces; the " << which << " mesh has none");
    }
  }

  void
  ScanMeshNormalEstimation::setRadiusResolutions (double radius)
  {
    if (!(radius > 0.0) || !std::isfinite (radius))
      PCL_TENSOR_THROW (BadArgumentException, "normal neighbourhood radius must be positive, got " << radius);
    radius_resolutions_ = radius;
  }

  void
  ScanMeshNormalEstimation::computeFaceAverage (ScanMesh& mesh) const
  {
    requireFaces (mesh, "input");
    storeOriented (mesh, areaWeightedSums (mesh));
  }

  void
  ScanMeshNormalEstimation::compute (ScanMesh& reduced, ScanMesh& fine, double resolution) const
  {
    requireFaces (reduced, "reduced");
    requireFaces (fine, "fine");
    // M_i always gets its face-average normals: verification's point-to-plane ICP runs on them,
    // whichever approach M'_i uses.
    const std::vector<Eigen::Vector3d> fine_sums = areaWeightedSums (fine);
    storeOriented (fine, fine_sums);
    if (method_ == Method::FACE_AVERAGE)
    {
      computeFaceAverage (reduced);
      return;
    }

    const float radius = static_cast<float> (radius_resolutions_ * (resolution > 0.0 ? resolution : meshResolution (fine)));
    pcl::BoundedNearestSearch search (radius);
    search.setInputCloud (*fine.cloud);
    std::vector<int> neighbours;
    // A reduced vertex whose fine neighbourhood gives no normal (no fine vertex within the radius,
    // or only isolated ones) keeps approach (a): M'_i's own faces always give one.
    std::vector<Eigen::Vector3d> sums = areaWeightedSums (reduced);
    for (std::size_t i = 0; i < reduced.cloud->size (); ++i)
    {
      // The corresponding vertex of M_i is the nearest one (reduction keeps vertices where they
      // were); its normal is the area-weighted average over the fine faces within the neighbourhood
      // (Section 2, second approach).
      float d2;
      const int nearest = search.nearest ((*reduced.cloud)[i].getVector3fMap (), radius, d2);
      if (nearest < 0)
        continue;
      search.radiusSearch ((*fine.cloud)[nearest].getVector3fMap (), radius, neighbours);
      Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
      for (const int j : neighbours)
        sum += fine_sums[j];
      if (sum.norm () > 0.0)
        sums[i] = sum;
    }
    storeOriented (reduced, sums);
  }
}
