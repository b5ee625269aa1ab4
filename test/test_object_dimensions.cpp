#include "test_utils.h"

#include <pcl/common/object_dimensions.h>
#include <pcl/common/tensor_exceptions.h>

#include <gtest/gtest.h>

#include <cmath>
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

// Dimensions a user gives are sorted as Eq. 1 sorts D; any dimension not positive leaves D unset.
TEST (ObjectDimensions, GivenDimensionsAreSortedAndUnsetWhenNotPositive)
{
  const pcl::ObjectDimensions given = pcl::givenObjectDimensions (Eigen::Vector3d (0.1, 0.3, 0.2));
  EXPECT_TRUE (given.isSet ());
  EXPECT_EQ (given.D, Eigen::Vector3d (0.3, 0.2, 0.1));
  for (const Eigen::Vector3d& bad : {Eigen::Vector3d (0.1, 0.0, 0.2), Eigen::Vector3d (-0.1, 0.3, 0.2), Eigen::Vector3d (0.0, 0.0, 0.0)})
  {
    const pcl::ObjectDimensions unset = pcl::givenObjectDimensions (bad);
    EXPECT_FALSE (unset.isSet ()) << bad.transpose ();
    EXPECT_EQ (unset.D, Eigen::Vector3d::Zero ());
  }
  EXPECT_FALSE (pcl::givenObjectDimensions (Eigen::Vector3d (0.1, std::nan (""), 0.2)).isSet ());
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

TEST (ObjectDimensions, RegisteredViewsAreMeasuredInTheBestOfTheirFrames)
{
  // An L of two strips that together fill a 2 x 1 box: their combined principal axes are tilted, so
  // the L sticks out of that box there; the long strip's own frame is the box's.
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i <= 200; ++i)
    for (int j = 0; j <= 20; ++j)
      points.emplace_back (0.01 * i, 0.01 * j, 0.0);
  const std::size_t second_view = points.size ();
  for (int i = 0; i <= 20; ++i)
    for (int j = 1; j <= 80; ++j)
      points.emplace_back (0.01 * i, 0.2 + 0.01 * j, 0.0);
  pcl::ObjectDimensions dims;
  dims.D = Eigen::Vector3d (2.0, 1.0, 0.0);

  const double combined_frame = pcl::dimensionExcess (pcl::principalExtents (points), dims, 2);
  std::cout << "excess in the combined principal frame: " << combined_frame << std::endl;
  EXPECT_GT (combined_frame, 0.05);
  EXPECT_NEAR (pcl::registeredDimensionExcess (points, {0, second_view}, dims, 2), 0.0, 1e-9);
  // Without the views' own frames it is Eq. 9 as written.
  EXPECT_DOUBLE_EQ (pcl::registeredDimensionExcess (points, {}, dims, 2), combined_frame);

  // The same, turned and moved anywhere.
  const Eigen::Affine3d pose = Eigen::Translation3d (5.0, -3.0, 2.0) * Eigen::AngleAxisd (0.7, Eigen::Vector3d (1, 2, 3).normalized ());
  std::vector<Eigen::Vector3d> moved;
  for (const auto& p : points)
    moved.push_back (pose * p);
  EXPECT_NEAR (pcl::registeredDimensionExcess (moved, {0, second_view}, dims, 2), 0.0, 1e-9);

  EXPECT_THROW (pcl::registeredDimensionExcess (points, {second_view, 0}, dims, 2), pcl::BadArgumentException);
  EXPECT_THROW (pcl::registeredDimensionExcess (points, {0, points.size () + 1}, dims, 2), pcl::BadArgumentException);
}
