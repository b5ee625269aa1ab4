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
  Eigen::Vector3d
  principalExtents (const std::vector<Eigen::Vector3d>& points)
  {
    // Two passes in double precision: centroid first, so that the covariance does not lose digits
    // to large coordinates (scans far from the origin).
    std::size_t n = 0;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero ();
    for (const auto& p : points)
      if (p.allFinite ())
      {
        centroid += p;
        ++n;
      }
    if (n < 3)
      PCL_TENSOR_THROW (InvalidScanException, "principal axes need at least 3 finite points, got " << n);
    centroid /= static_cast<double> (n);

    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero ();
    for (const auto& p : points)
      if (p.allFinite ())
        covariance.noalias () += (p - centroid) * (p - centroid).transpose ();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (covariance);
    const Eigen::Matrix3d axes = solver.eigenvectors (); // P_i in Eq. 1

    Eigen::Vector3d lo = Eigen::Vector3d::Constant (std::numeric_limits<double>::max ());
    Eigen::Vector3d hi = -lo;
    for (const auto& p : points)
      if (p.allFinite ())
      {
        const Eigen::Vector3d q = axes.transpose () * (p - centroid);
        lo = lo.cwiseMin (q);
        hi = hi.cwiseMax (q);
      }
    Eigen::Vector3d extents = hi - lo;
    std::sort (extents.data (), extents.data () + 3, std::greater<> ());
    return extents;
  }

  double
  dimensionExcess (const Eigen::Vector3d& extents, const ObjectDimensions& dims, int checked)
  {
    return (extents - dims.D).head (std::clamp (checked, 1, 3)).maxCoeff ();
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
    if (views.empty ())
      PCL_TENSOR_THROW (InvalidScanException, "object dimensions need at least one view");
    ObjectDimensions dims;
    for (const auto* view : views)
      dims.D = dims.D.cwiseMax (principalExtents (*view));
    return dims;
  }

#define PCL_TENSOR_INSTANTIATE_DIMENSIONS(T)                                                         \
  template Eigen::Vector3d principalExtents<T> (const pcl::PointCloud<T>&);                       \
  template Eigen::Vector3d principalExtents<T> (const std::vector<const pcl::PointCloud<T>*>&);   \
  template ObjectDimensions computeObjectDimensions<T> (const std::vector<const pcl::PointCloud<T>*>&);

  PCL_TENSOR_INSTANTIATE_DIMENSIONS (pcl::PointXYZ)
  PCL_TENSOR_INSTANTIATE_DIMENSIONS (pcl::PointNormal)
}
