/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/registration/global_verification.h>
#include <pcl/common/tensor_exceptions.h>

namespace pcl
{
  namespace registration
  {
    namespace
    {
      void
      appendTransformed (const pcl::PointCloud<pcl::PointNormal>& cloud, const Eigen::Affine3d& pose,
                         std::vector<Eigen::Vector3d>& points)
      {
        points.reserve (points.size () + cloud.size ());
        for (const auto& p : cloud)
          points.push_back (pose * p.getVector3fMap ().cast<double> ());
      }
    }

    GlobalVerification::GlobalVerification (const ObjectDimensions& dims, double resolution, const GlobalVerificationParams& params)
      : dims_ (dims), resolution_ (resolution), params_ (params)
    {
      if (!(resolution > 0.0) || !(params.tolerance >= 0.0))
        PCL_TENSOR_THROW (BadArgumentException, "global verification needs a positive resolution and a non-negative tolerance");
    }

    void
    GlobalVerification::addView (const pcl::PointCloud<pcl::PointNormal>& cloud, const Eigen::Affine3d& pose)
    {
      view_starts_.push_back (points_.size ());
      appendTransformed (cloud, pose, points_);
    }

    double
    GlobalVerification::excess (const pcl::PointCloud<pcl::PointNormal>& cloud, const Eigen::Affine3d& pose) const
    {
      std::vector<Eigen::Vector3d> points = points_;
      std::vector<std::size_t> view_starts = view_starts_;
      view_starts.push_back (points.size ());
      appendTransformed (cloud, pose, points);
      return registeredDimensionExcess (points, view_starts, dims_, params_.checked_dimensions) / resolution_;
    }
  }
}
