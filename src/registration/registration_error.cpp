/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/registration/registration_error.h>
#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace pcl
{
  double
  rotationErrorDeg (const Eigen::Matrix3d& rotation, const Eigen::Matrix3d& ground_truth)
  {
    // R_gt^-1 = R_gt^T for a rotation (Eq. 10).
    const Eigen::Matrix3d rd = rotation * ground_truth.transpose ();
    // Eq. 10's arccos((tr - 1) / 2), as atan2(sin, cos): sin theta is the norm of the skew part. Near
    // 0 the arccos form loses the angle to the rounding of the trace (a float pose's 1e-7 is 0.03 deg),
    // while the skew part keeps it to 1e-5 deg.
    const Eigen::Vector3d skew (rd (2, 1) - rd (1, 2), rd (0, 2) - rd (2, 0), rd (1, 0) - rd (0, 1));
    return std::atan2 (0.5 * skew.norm (), 0.5 * (rd.trace () - 1.0)) * 180.0 / M_PI;
  }

  double
  translationErrorResolutions (const Eigen::Vector3d& translation, const Eigen::Vector3d& ground_truth,
                               double resolution)
  {
    if (!(resolution > 0.0) || !std::isfinite (resolution))
      PCL_TENSOR_THROW (pcl::BadArgumentException, "translation error needs d_res > 0, got " << resolution);
    return (translation - ground_truth).norm () / resolution;
  }

  RegistrationError
  registrationError (const Eigen::Affine3d& estimate, const Eigen::Affine3d& ground_truth, double resolution)
  {
    RegistrationError e;
    e.translation_resolutions = translationErrorResolutions (estimate.translation (), ground_truth.translation (),
                                                             resolution);
    e.rotation_deg = rotationErrorDeg (estimate.linear (), ground_truth.linear ());
    return e;
  }

  namespace
  {
    pcl::PointCloud<pcl::PointXYZ>::Ptr
    finiteTransformed (const pcl::PointCloud<pcl::PointXYZ>& in, const Eigen::Affine3d& pose)
    {
      pcl::PointCloud<pcl::PointXYZ>::Ptr out (new pcl::PointCloud<pcl::PointXYZ>);
      out->reserve (in.size ());
      for (const auto& p : in)
        if (pcl::isXYZFinite (p))
        {
          pcl::PointXYZ q;
          q.getVector3fMap () = (pose * p.getVector3fMap ().cast<double> ()).cast<float> ();
          out->push_back (q);
        }
      if (out->empty ())
        PCL_TENSOR_THROW (InvalidScanException, "viewOverlap: a view has no finite point");
      return out;
    }
  }

  double
  viewOverlap (const pcl::PointCloud<pcl::PointXYZ>& cloud_a, const Eigen::Affine3d& pose_a,
               const pcl::PointCloud<pcl::PointXYZ>& cloud_b, const Eigen::Affine3d& pose_b,
               double max_distance)
  {
    if (!(max_distance > 0.0) || !std::isfinite (max_distance))
      PCL_TENSOR_THROW (pcl::BadArgumentException, "viewOverlap needs a positive distance, got " << max_distance);
    auto a = finiteTransformed (cloud_a, pose_a);
    auto b = finiteTransformed (cloud_b, pose_b);
    // Eq. 14 divides by the smaller vertex count, so the smaller view is the one queried.
    if (a->size () > b->size ())
      std::swap (a, b);
    pcl::KdTreeFLANN<pcl::PointXYZ> tree;
    tree.setInputCloud (b);
    const double max_sq = max_distance * max_distance;
    pcl::Indices index (1);
    std::vector<float> sq (1);
    std::size_t matched = 0;
    for (const auto& p : *a)
      if (tree.nearestKSearch (p, 1, index, sq) == 1 && sq[0] <= max_sq)
        ++matched;
    return static_cast<double> (matched) / static_cast<double> (a->size ());
  }

  Eigen::Affine3d
  bestFitCommonFrame (const std::vector<const pcl::PointCloud<pcl::PointXYZ>*>& views,
                      const std::vector<Eigen::Affine3d, Eigen::aligned_allocator<Eigen::Affine3d>>& estimates,
                      const std::vector<Eigen::Affine3d, Eigen::aligned_allocator<Eigen::Affine3d>>& truth,
                      std::size_t samples_per_view)
  {
    if (views.size () != estimates.size () || views.size () != truth.size ())
      PCL_TENSOR_THROW (pcl::BadArgumentException, "bestFitCommonFrame needs one estimate and one ground truth per view, got "
                        << views.size () << " views, " << estimates.size () << " estimates and " << truth.size () << " truths");
    std::vector<Eigen::Vector3d> from, to;
    for (std::size_t i = 0; i < views.size (); ++i)
    {
      if (!views[i])
        continue;
      std::vector<std::size_t> finite;
      for (std::size_t k = 0; k < views[i]->size (); ++k)
        if (pcl::isXYZFinite ((*views[i])[k]))
          finite.push_back (k);
      const std::size_t step = std::max<std::size_t> (1, finite.size () / std::max<std::size_t> (1, samples_per_view));
      for (std::size_t k = 0; k < finite.size (); k += step)
      {
        const Eigen::Vector3d p = (*views[i])[finite[k]].getVector3fMap ().cast<double> ();
        from.push_back (estimates[i] * p);
        to.push_back (truth[i] * p);
      }
    }
    if (from.size () < 3)
      PCL_TENSOR_THROW (pcl::BadArgumentException, "bestFitCommonFrame needs at least 3 finite points, got " << from.size ());
    Eigen::Matrix3Xd src (3, from.size ()), dst (3, to.size ());
    for (std::size_t k = 0; k < from.size (); ++k)
    {
      src.col (k) = from[k];
      dst.col (k) = to[k];
    }
    return Eigen::Affine3d (Eigen::umeyama (src, dst, false));
  }
}
