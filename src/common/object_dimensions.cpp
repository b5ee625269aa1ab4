/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/common/object_dimensions.h>
#include <pcl/common/tensor_exceptions.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <functional>

namespace pcl
{
  namespace
  {
    using PointIterator = std::vector<Eigen::Vector3d>::const_iterator;

    /** Principal axes, as columns (P_i in Eq. 1), of the finite points in [first, last). Two passes in
      * double precision: centroid first, so that the covariance does not lose digits to large
      * coordinates (scans far from the origin). */
    Eigen::Matrix3d
    principalAxes (PointIterator first, PointIterator last)
    {
      std::size_t n = 0;
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero ();
      for (auto p = first; p != last; ++p)
        if (p->allFinite ())
        {
          centroid += *p;
          ++n;
        }
      if (n < 3)
        PCL_TENSOR_THROW (InvalidScanException, "principal axes need at least 3 finite points, got " << n);
      centroid /= static_cast<double> (n);
      Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero ();
      for (auto p = first; p != last; ++p)
        if (p->allFinite ())
          covariance.noalias () += (*p - centroid) * (*p - centroid).transpose ();
      return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> (covariance).eigenvectors ();
    }

    /** Extents of the finite points along the columns of \a axes, sorted from largest to smallest. */
    Eigen::Vector3d
    extentsAlong (const std::vector<Eigen::Vector3d>& points, const Eigen::Matrix3d& axes)
    {
      const auto origin = std::find_if (points.begin (), points.end (), [] (const Eigen::Vector3d& p) { return p.allFinite (); });
      Eigen::Vector3d lo = Eigen::Vector3d::Zero (), hi = Eigen::Vector3d::Zero ();
      for (const auto& p : points)
        if (p.allFinite ())
        {
          // Relative to one of the points, which keeps the digits that large coordinates would take.
          const Eigen::Vector3d q = axes.transpose () * (p - *origin);
          lo = lo.cwiseMin (q);
          hi = hi.cwiseMax (q);
        }
      Eigen::Vector3d extents = hi - lo;
      std::sort (extents.data (), extents.data () + 3, std::greater<> ());
      return extents;
    }
  }

  Eigen::Vector3d
  principalExtents (const std::vector<Eigen::Vector3d>& points)
  {
    return extentsAlong (points, principalAxes (points.begin (), points.end ()));
  }

  double
  dimensionExcess (const Eigen::Vector3d& extents, const ObjectDimensions& dims, int checked)
  {
    return (extents - dims.D).head (std::clamp (checked, 1, 3)).maxCoeff ();
  }

  double
  registeredDimensionExcess (const std::vector<Eigen::Vector3d>& points, const std::vector<std::size_t>& view_starts,
                             const ObjectDimensions& dims, int checked)
  {
    double excess = dimensionExcess (principalExtents (points), dims, checked);
    for (std::size_t v = 0; v < view_starts.size (); ++v)
    {
      const std::size_t end = v + 1 < view_starts.size () ? view_starts[v + 1] : points.size ();
      if (view_starts[v] > end || end > points.size ())
        PCL_TENSOR_THROW (BadArgumentException, "view " << v << " starts outside the points or after the next view");
      const auto first = points.begin () + static_cast<std::ptrdiff_t> (view_starts[v]);
      const auto last = points.begin () + static_cast<std::ptrdiff_t> (end);
      if (std::count_if (first, last, [] (const Eigen::Vector3d& p) { return p.allFinite (); }) < 3)
        continue;  // a view too small to have axes of its own
      excess = std::min (excess, dimensionExcess (extentsAlong (points, principalAxes (first, last)), dims, checked));
    }
    return excess;
  }

  template <typename PointT> Eigen::Vector3d
  principalExtents (const std::vector<const pcl::PointCloud<PointT>*>& clouds)
  {
    std::vector<Eigen::Vector3d> points;
    for (const auto* cloud : clouds)
      for (const auto& p : *cloud)
        points.push_back (p.getVector3fMap ().template cast<double> ());
    return principalExtents (points);
  }

  template <typename PointT> Eigen::Vector3d
  principalExtents (const pcl::PointCloud<PointT>& cloud)
  {
    return principalExtents<PointT> (std::vector<const pcl::PointCloud<PointT>*>{&cloud});
  }

  template <typename PointT> ObjectDimensions
  computeObjectDimensions (const std::vector<const pcl::PointCloud<PointT>*>& views)
  {
    std::vector<Eigen::Vector3d> extents;
    extents.reserve (views.size ());
    for (const auto* view : views)
      extents.push_back (principalExtents (*view));
    return objectDimensionsFromExtents (extents);
  }

  ObjectDimensions
  objectDimensionsFromExtents (const std::vector<Eigen::Vector3d>& extents)
  {
    if (extents.empty ())
      PCL_TENSOR_THROW (InvalidScanException, "object dimensions need at least one view");
    ObjectDimensions dims;
    for (const auto& e : extents)
      dims.D = dims.D.cwiseMax (e);
    return dims;
  }

  ObjectDimensions
  givenObjectDimensions (const Eigen::Vector3d& D)
  {
    ObjectDimensions dims;
    if ((D.array () > 0.0).all ())
    {
      dims.D = D;
      std::sort (dims.D.data (), dims.D.data () + 3, std::greater<> ());
    }
    return dims;
  }

#define PCL_TENSOR_INSTANTIATE_DIMENSIONS(T)                                                         \
  template Eigen::Vector3d principalExtents<T> (const pcl::PointCloud<T>&);                       \
  template Eigen::Vector3d principalExtents<T> (const std::vector<const pcl::PointCloud<T>*>&);   \
  template ObjectDimensions computeObjectDimensions<T> (const std::vector<const pcl::PointCloud<T>*>&);

  PCL_TENSOR_INSTANTIATE_DIMENSIONS (pcl::PointXYZ)
  PCL_TENSOR_INSTANTIATE_DIMENSIONS (pcl::PointNormal)
}
