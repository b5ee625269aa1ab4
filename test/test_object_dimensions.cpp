#include "test_utils.h"

#include <pcl/common/object_dimensions.h>
#include <pcl/common/tensor_exceptions.h>

#include <gtest/gtest.h>

#include <random>

namespace
{
  /** Points on the surface of an a x b x c box, rotated and translated at random. */
  pcl::PointCloud<pcl::PointXYZ>
  randomBox (const Eigen::Vector3d& size, std::mt19937& rng)
  {
    const Eigen::Isometry3d pose = pcl_tensor_test::randomRigidTransform (rng, 0.5);
    const Eigen::Matrix3d q = pose.linear ();
    const Eigen::Vector3d t = pose.translation ();
    pcl::PointCloud<pcl::PointXYZ> cloud;
    for (int corner = 0; corner < 8; ++corner)
    {
      const Eigen::Vector3d p ((corner & 1 ? 0.5 : -0.5) * size.x (), (corner & 2 ? 0.5 : -0.5) * size.y (),
                               (corner & 4 ? 0.5 : -0.5) * size.z ());
      const Eigen::Vector3d w = q * p + t;
      cloud.push_back (pcl::PointXYZ (static_cast<float> (w.x ()), static_cast<float> (w.y ()), static_cast<float> (w.z ())));
    }
    return cloud;
  }
}

TEST (ObjectDimensions, BoxOfKnownSizeAtRandomPoseGivesDExactly)
{
  // Eq. 1 on the corners of a 0.3 x 0.2 x 0.1 box under random rigid motions, in double precision.
  std::mt19937 rng (42);
  const Eigen::Vector3d size (0.3, 0.2, 0.1);
  for (int trial = 0; trial < 50; ++trial)
  {
    const Eigen::Isometry3d pose = pcl_tensor_test::randomRigidTransform (rng, 1.0);
    const Eigen::Matrix3d q = pose.linear ();
    const Eigen::Vector3d t = pose.translation ();
    std::vector<Eigen::Vector3d> corners;
    for (int corner = 0; corner < 8; ++corner)
      corners.push_back (q * Eigen::Vector3d ((corner & 1 ? 0.5 : -0.5) * size.x (), (corner & 2 ? 0.5 : -0.5) * size.y (),
                                              (corner & 4 ? 0.5 : -0.5) * size.z ()) + t);
    const Eigen::Vector3d d = pcl::principalExtents (corners);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR (d[k], size[k], 1e-9 * size[k]) << "trial " << trial;
  }
}

TEST (ObjectDimensions, FloatCloudOfRotatedBoxIsExactToFloatPrecision)
{
  std::mt19937 rng (5);
  const Eigen::Vector3d size (0.3, 0.2, 0.1);
  for (int trial = 0; trial < 20; ++trial)
  {
    const Eigen::Vector3d d = pcl::principalExtents (randomBox (size, rng));
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR (d[k], size[k], 1e-6 * size[k] + 1e-7) << "trial " << trial;  // float coordinates
  }
}

TEST (ObjectDimensions, DIsTheElementwiseMaximumOverViewsAndDerivedParametersFollowEq2And3)
{
  std::mt19937 rng (3);
  const auto a = randomBox (Eigen::Vector3d (0.3, 0.05, 0.01), rng);
  const auto b = randomBox (Eigen::Vector3d (0.1, 0.09, 0.08), rng);
  const pcl::ObjectDimensions dims = pcl::computeObjectDimensions<pcl::PointXYZ> ({&a, &b});
  EXPECT_NEAR (dims.D[0], 0.3, 1e-6);
  EXPECT_NEAR (dims.D[1], 0.09, 1e-6);
  EXPECT_NEAR (dims.D[2], 0.08, 1e-6);
  const double mean = (0.3 + 0.09 + 0.08) / 3.0;
  EXPECT_NEAR (dims.dMin (), mean / 6.0, 1e-6);
  EXPECT_NEAR (dims.dMax (), mean / 4.0, 1e-6);
  EXPECT_NEAR (dims.binSize (), mean / 30.0, 1e-6);
  EXPECT_NEAR (dims.verificationTolerance (), mean / 10.0, 1e-6);
}

TEST (ObjectDimensions, FarFromOriginKeepsPrecision)
{
  // Scans offset by 1e3 m must give the same extents: the covariance is taken about the centroid.
  std::mt19937 rng (11);
  auto cloud = randomBox (Eigen::Vector3d (0.3, 0.2, 0.1), rng);
  for (auto& p : cloud)
    p.x += 1000.0f;
  const Eigen::Vector3d d = pcl::principalExtents (cloud);
  EXPECT_NEAR (d[0], 0.3, 1e-3);
  EXPECT_NEAR (d[2], 0.1, 1e-3);
}

TEST (ObjectDimensions, TooFewFinitePointsThrow)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.push_back (pcl::PointXYZ (0, 0, 0));
  cloud.push_back (pcl::PointXYZ (std::nanf (""), 0, 0));
  cloud.push_back (pcl::PointXYZ (1, 0, 0));
  EXPECT_THROW (pcl::principalExtents (cloud), pcl::InvalidScanException);
  EXPECT_THROW (pcl::computeObjectDimensions<pcl::PointXYZ> ({}), pcl::InvalidScanException);
}
