/*
 * pcl_tensor: known-answer tests of ViewExtents, the dimension checks' summary of a view.
 */
#include "test_utils.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/common/view_extents.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace
{
  /** A wavy sheet of \a rows x \a cols points in row order, as a range image gives them, with noise. */
  pcl::PointCloud<pcl::PointXYZ>
  wavySheet (int rows, int cols, const Eigen::Vector3d& offset, std::mt19937& rng)
  {
    std::normal_distribution<double> noise (0.0, 1e-4);
    pcl::PointCloud<pcl::PointXYZ> cloud;
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j)
      {
        const double x = 1e-3 * j, y = 1e-3 * i, z = 0.02 * std::sin (40.0 * x) * std::cos (25.0 * y) + noise (rng);
        const Eigen::Vector3d p = offset + Eigen::Vector3d (x, y, z);
        cloud.push_back (pcl::PointXYZ (static_cast<float> (p.x ()), static_cast<float> (p.y ()), static_cast<float> (p.z ())));
      }
    return cloud;
  }

  std::vector<Eigen::Vector3d>
  finitePoints (const pcl::PointCloud<pcl::PointXYZ>& cloud)
  {
    std::vector<Eigen::Vector3d> points;
    for (const auto& p : cloud)
      if (p.getVector3fMap ().allFinite ())
        points.push_back (p.getVector3fMap ().cast<double> ());
    return points;
  }
}

TEST (ViewExtents, SupportIsTheMaximumOverEveryPoint)
{
  std::mt19937 rng (2006);
  auto cloud = wavySheet (90, 110, Eigen::Vector3d (0.3, -0.2, 1.5), rng);
  cloud[17].x = std::numeric_limits<float>::quiet_NaN ();  // a hole: not a point
  const pcl::ViewExtents extents (cloud);
  const auto points = finitePoints (cloud);
  ASSERT_EQ (extents.size (), points.size ());
  std::normal_distribution<double> gauss;
  for (int trial = 0; trial < 200; ++trial)
  {
    const Eigen::Vector3d d = Eigen::Vector3d (gauss (rng), gauss (rng), gauss (rng)).normalized ();
    double brute = -std::numeric_limits<double>::infinity ();
    for (const auto& p : points)
      brute = std::max (brute, d.dot (p));
    EXPECT_EQ (extents.support (d), brute) << "direction " << d.transpose ();
  }
  EXPECT_EQ (pcl::ViewExtents ().support (Eigen::Vector3d::UnitX ()), -std::numeric_limits<double>::infinity ());
}

TEST (ViewExtents, RegisteredExcessIsTheOneOverEveryPoint)
{
  std::mt19937 rng (7);
  const auto model = wavySheet (80, 120, Eigen::Vector3d::Zero (), rng);
  const auto scene = wavySheet (100, 70, Eigen::Vector3d (0.05, 0.0, 0.01), rng);
  const pcl::ViewExtents model_extents (model), scene_extents (scene);
  pcl::ObjectDimensions dims;
  dims.D = Eigen::Vector3d (0.12, 0.09, 0.03);
  for (int trial = 0; trial < 20; ++trial)
  {
    const Eigen::Isometry3d pose = pcl_tensor_test::randomRigidTransform (rng, 0.1);
    std::vector<Eigen::Vector3d> points = finitePoints (model);
    const std::size_t second_view = points.size ();
    for (const auto& p : finitePoints (scene))
      points.push_back (pose * p);
    for (int checked = 1; checked <= 3; ++checked)
      EXPECT_NEAR (pcl::registeredDimensionExcess (model_extents, scene_extents, pose.matrix (), dims, checked),
                   pcl::registeredDimensionExcess (points, {0, second_view}, dims, checked), 1e-12);
  }
}

TEST (ViewExtents, TooFewPointsThrow)
{
  pcl::PointCloud<pcl::PointXYZ> two;
  two.push_back (pcl::PointXYZ (0.0f, 0.0f, 0.0f));
  two.push_back (pcl::PointXYZ (1.0f, 0.0f, 0.0f));
  EXPECT_THROW (pcl::registeredDimensionExcess (pcl::ViewExtents (two), pcl::ViewExtents (), Eigen::Matrix4d::Identity (),
                                                pcl::ObjectDimensions ()),
                pcl::InvalidScanException);
}
