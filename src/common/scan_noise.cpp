/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/common/scan_noise.h>
#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/search/bounded_nearest_search.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace pcl
{
  namespace
  {
    struct Plane
    {
      Eigen::Vector3d point, normal;
    };

    Eigen::Vector3d
    at (const pcl::PointCloud<pcl::PointNormal>& cloud, int i)
    {
      return cloud[i].getVector3fMap ().cast<double> ();
    }

    /** The least-squares plane through \a cloud's points \a neighbours. */
    Plane
    fitPlane (const pcl::PointCloud<pcl::PointNormal>& cloud, const std::vector<int>& neighbours)
    {
      Eigen::Vector3d mean = Eigen::Vector3d::Zero ();
      for (const int i : neighbours)
        mean += at (cloud, i);
      mean /= static_cast<double> (neighbours.size ());
      Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero ();
      for (const int i : neighbours)
        scatter += (at (cloud, i) - mean) * (at (cloud, i) - mean).transpose ();
      // The normal is the direction of least scatter (eigenvalues come in ascending order).
      return {mean, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> (scatter).eigenvectors ().col (0)};
    }

    /** The points of \a candidates within \a radius of \a centre across \a plane's normal: a cylinder
      * along the normal, which keeps a point whatever its noise along the normal (a sphere would drop the
      * noisiest points and bias sigma low: 0.78 sigma at sigma = radius / 3). */
    std::vector<int>
    inCylinder (const pcl::PointCloud<pcl::PointNormal>& cloud, const std::vector<int>& candidates, const Eigen::Vector3d& centre,
                const Plane& plane, double radius)
    {
      std::vector<int> kept;
      for (const int i : candidates)
      {
        const Eigen::Vector3d d = at (cloud, i) - centre;
        if ((d - d.dot (plane.normal) * plane.normal).squaredNorm () <= radius * radius)
          kept.push_back (i);
      }
      return kept;
    }
  }

  double
  estimateScanNoise (const pcl::PointCloud<pcl::PointNormal>& points, double radius, std::size_t samples)
  {
    // The wider search (2 radius) must stay a finite float too.
    if (!(radius > 0.0) || !std::isfinite (static_cast<float> (2.0 * radius)) || samples == 0)
      PCL_TENSOR_THROW (BadArgumentException, "scan noise needs a positive radius and sample count, got " << radius << " and "
                        << samples);
    std::vector<std::size_t> finite;
    for (std::size_t i = 0; i < points.size (); ++i)
      if (pcl::isXYZFinite (points[i]))
        finite.push_back (i);
    if (finite.empty ())
      return 0.0;
    pcl::BoundedNearestSearch search (static_cast<float> (radius));
    search.setInputCloud (points);
    const std::size_t step = std::max<std::size_t> (1, finite.size () / samples);
    std::vector<double> residuals;
    std::vector<int> sphere, wide;
    for (std::size_t k = step / 2; k < finite.size (); k += step)
    {
      // A first plane from the sphere, then the cylinder about its normal, refitted.
      const Eigen::Vector3f centre = points[finite[k]].getVector3fMap ();
      if (search.radiusSearch (centre, static_cast<float> (radius), sphere) < 4)
        continue;
      search.radiusSearch (centre, static_cast<float> (2.0 * radius), wide);
      const std::vector<int> cylinder = inCylinder (points, wide, centre.cast<double> (), fitPlane (points, sphere), radius);
      const Plane plane = fitPlane (points, cylinder);
      for (const int i : cylinder)
        residuals.push_back (std::abs (plane.normal.dot (at (points, i) - plane.point)));
    }
    if (residuals.empty ())
      return 0.0;
    const auto middle = residuals.begin () + static_cast<std::ptrdiff_t> (residuals.size () / 2);
    std::nth_element (residuals.begin (), middle, residuals.end ());
    return 1.4826 * *middle;
  }
}
