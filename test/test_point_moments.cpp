/*
 * pcl_tensor: known-answer tests of PointMoments, the count, centroid and scatter that the dimension
 * checks take principal axes from.
 */
#include <pcl/common/point_moments.h>

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace
{
  std::vector<Eigen::Vector3d>
  randomPoints (std::size_t n, const Eigen::Vector3d& offset, std::mt19937& rng)
  {
    std::uniform_real_distribution<double> u (-0.1, 0.1);
    std::vector<Eigen::Vector3d> points (n);
    for (auto& p : points)
      p = offset + Eigen::Vector3d (u (rng), 2.0 * u (rng), 0.3 * u (rng));
    return points;
  }
}

// Four points at the corners of a square of side 2 about (1, 1, 5): centroid (1, 1, 5), scatter
// diag(4, 4, 0).
TEST (PointMoments, SquareHasItsCentreAndScatter)
{
  const std::vector<Eigen::Vector3d> square{{0, 0, 5}, {2, 0, 5}, {2, 2, 5}, {0, 2, 5}};
  const pcl::PointMoments m = pcl::computePointMoments (square);
  EXPECT_EQ (m.count, 4.0);
  EXPECT_TRUE (m.mean.isApprox (Eigen::Vector3d (1, 1, 5)));
  EXPECT_TRUE (m.scatter.isApprox (Eigen::Vector3d (4, 4, 0).asDiagonal ().toDenseMatrix ()));
  const pcl::PointMoments none = pcl::computePointMoments ({});
  EXPECT_EQ (none.count, 0.0);
  EXPECT_TRUE (none.scatter.isZero ());
}

// The moments of two sets united under a pose are those of every point, the second set moved, in one
// pass; uniting with an empty set changes nothing.
TEST (PointMoments, UnitedSetsHaveTheMomentsOfAllTheirPoints)
{
  std::mt19937 rng (23);
  const auto a = randomPoints (500, Eigen::Vector3d (3.0, -1.0, 40.0), rng);
  const auto b = randomPoints (300, Eigen::Vector3d (0.2, 0.1, -0.3), rng);
  const Eigen::Affine3d pose = Eigen::Translation3d (0.5, 1.0, 40.0) * Eigen::AngleAxisd (0.7, Eigen::Vector3d (1, 2, 3).normalized ());
  std::vector<Eigen::Vector3d> all = a;
  for (const auto& p : b)
    all.push_back (pose * p);
  const pcl::PointMoments direct = pcl::computePointMoments (all);
  const pcl::PointMoments united = pcl::unitePointMoments (pcl::computePointMoments (a), pcl::computePointMoments (b), pose);
  EXPECT_EQ (united.count, 800.0);
  EXPECT_LT ((united.mean - direct.mean).norm (), 1e-12);
  EXPECT_LT ((united.scatter - direct.scatter).norm (), 1e-9 * direct.scatter.norm ());
  const pcl::PointMoments same = pcl::unitePointMoments (pcl::computePointMoments (a), pcl::PointMoments (), pose);
  EXPECT_EQ (same.count, 500.0);
  EXPECT_TRUE (same.mean.isApprox (pcl::computePointMoments (a).mean));
  EXPECT_TRUE (same.scatter.isApprox (pcl::computePointMoments (a).scatter));
}
