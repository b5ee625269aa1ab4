/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/common/view_extents.h>
#include <pcl/common/tensor_exceptions.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <functional>
#include <limits>

namespace pcl
{
  template <typename PointT>
  ViewExtents::ViewExtents (const pcl::PointCloud<PointT>& cloud)
  {
    points_.reserve (cloud.size ());
    for (const auto& p : cloud)
      if (p.getVector3fMap ().allFinite ())
        points_.push_back (p.getVector3fMap ().template cast<double> ());
    moments_ = computePointMoments (points_);
    for (std::size_t first = 0; first < points_.size (); first += kRun)
    {
      const std::size_t last = std::min (first + kRun, points_.size ());
      Eigen::Vector3d low = points_[first], high = points_[first];
      for (std::size_t k = first + 1; k < last; ++k)
      {
        low = low.cwiseMin (points_[k]);
        high = high.cwiseMax (points_[k]);
      }
      box_centres_.push_back (0.5 * (low + high));
      box_halves_.push_back (0.5 * (high - low));
    }
  }

  double
  ViewExtents::bound (std::size_t r, const Eigen::Vector3d& direction) const
  {
    return direction.dot (box_centres_[r]) + direction.cwiseAbs ().dot (box_halves_[r]);
  }

  double
  ViewExtents::exact (std::size_t r, const Eigen::Vector3d& direction) const
  {
    const std::size_t first = r * kRun, last = std::min (first + kRun, points_.size ());
    double best = -std::numeric_limits<double>::infinity ();
    for (std::size_t k = first; k < last; ++k)
      best = std::max (best, direction.dot (points_[k]));
    return best;
  }

  double
  ViewExtents::support (const Eigen::Vector3d& direction) const
  {
    if (box_centres_.empty ())
      return -std::numeric_limits<double>::infinity ();
    // The box that promises most first, then only the boxes that could still beat it.
    std::size_t top = 0;
    double top_bound = bound (0, direction);
    for (std::size_t r = 1; r < box_centres_.size (); ++r)
    {
      const double b = bound (r, direction);
      if (b > top_bound)
        top = r, top_bound = b;
    }
    double best = exact (top, direction);
    for (std::size_t r = 0; r < box_centres_.size (); ++r)
      if (r != top && bound (r, direction) > best)
        best = std::max (best, exact (r, direction));
    return best;
  }

  namespace
  {
    /** Extents along \a axes (columns) of \a model and \a scene moved by \a t, largest first. */
    Eigen::Vector3d
    unionExtents (const ViewExtents& model, const ViewExtents& scene, const Eigen::Matrix4d& t, const Eigen::Matrix3d& axes)
    {
      const Eigen::Matrix3d r = t.topLeftCorner<3, 3> ();
      const Eigen::Vector3d shift = t.topRightCorner<3, 1> ();
      Eigen::Vector3d extents;
      for (int k = 0; k < 3; ++k)
      {
        // a . (R p + t) = (R^T a) . p + a . t
        const Eigen::Vector3d a = axes.col (k), in_scene = r.transpose () * a;
        const double high = std::max (model.support (a), scene.support (in_scene) + a.dot (shift));
        const double low = -std::max (model.support (-a), scene.support (-in_scene) - a.dot (shift));
        extents[k] = high - low;
      }
      std::sort (extents.data (), extents.data () + 3, std::greater<> ());
      return extents;
    }

    Eigen::Matrix3d
    axesOf (const Eigen::Matrix3d& scatter)
    {
      return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> (scatter).eigenvectors ();
    }
  }

  double
  registeredDimensionExcess (const ViewExtents& model, const ViewExtents& scene, const Eigen::Matrix4d& t,
                             const ObjectDimensions& dims, int checked)
  {
    const PointMoments both = unitePointMoments (model.moments (), scene.moments (), Eigen::Affine3d (t));
    if (both.count < 3.0)
      PCL_TENSOR_THROW (InvalidScanException, "principal axes need at least 3 finite points, got " << both.count);
    const Eigen::Matrix3d r = t.topLeftCorner<3, 3> ();
    double excess = dimensionExcess (unionExtents (model, scene, t, axesOf (both.scatter)), dims, checked);
    // Each view's own frame, as registeredDimensionExcess() takes it; too small a view has none.
    if (model.size () >= 3)
      excess = std::min (excess, dimensionExcess (unionExtents (model, scene, t, axesOf (model.moments ().scatter)), dims, checked));
    if (scene.size () >= 3)
      excess = std::min (excess, dimensionExcess (unionExtents (model, scene, t, r * axesOf (scene.moments ().scatter)), dims, checked));
    return excess;
  }

  template ViewExtents::ViewExtents (const pcl::PointCloud<pcl::PointXYZ>&);
  template ViewExtents::ViewExtents (const pcl::PointCloud<pcl::PointNormal>&);
}
