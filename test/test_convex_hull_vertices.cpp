/*
 * pcl_tensor: the convex hull's vertices, from qhull directly, are those pcl::ConvexHull finds.
 */
#include "common/convex_hull_vertices.h"

#include <pcl/surface/convex_hull.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using pcl::detail::convexHullVertices;

namespace
{
  std::vector<std::array<float, 3>>
  sorted (const std::vector<Eigen::Vector3f>& points)
  {
    std::vector<std::array<float, 3>> out;
    for (const auto& p : points)
      out.push_back ({p.x (), p.y (), p.z ()});
    std::sort (out.begin (), out.end ());
    return out;
  }
}

TEST (ConvexHullVertices, ACubeWithPointsInsideHasItsEightCorners)
{
  std::vector<Eigen::Vector3f> points;
  std::mt19937 rng (3);
  std::uniform_real_distribution<float> inside (0.05f, 0.95f);
  for (int i = 0; i < 500; ++i)
    points.emplace_back (inside (rng), inside (rng), inside (rng));
  std::vector<Eigen::Vector3f> corners;
  for (int c = 0; c < 8; ++c)
    corners.emplace_back (static_cast<float> (c & 1), static_cast<float> ((c >> 1) & 1), static_cast<float> ((c >> 2) & 1));
  points.insert (points.begin () + 100, corners.begin (), corners.end ());
  EXPECT_EQ (sorted (convexHullVertices (points)), sorted (corners));
}

TEST (ConvexHullVertices, SameVerticesAsPclConvexHull)
{
  // A bumpy cap, as a range scan's points are.
  std::mt19937 rng (5);
  std::normal_distribution<float> noise (0.0f, 0.002f);
  std::vector<Eigen::Vector3f> points;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 50; ++j)
    {
      const float x = 0.01f * i - 0.3f, y = 0.01f * j - 0.25f;
      const Eigen::Vector3f p (x, y, 0.5f - x * x - 2.0f * y * y + noise (rng));
      points.push_back (p);
      cloud->push_back (pcl::PointXYZ (p.x (), p.y (), p.z ()));
    }
  pcl::ConvexHull<pcl::PointXYZ> hull;
  hull.setInputCloud (cloud);
  hull.setDimension (3);
  pcl::PointCloud<pcl::PointXYZ> pcl_vertices;
  hull.reconstruct (pcl_vertices);
  std::vector<Eigen::Vector3f> expected;
  for (const auto& v : pcl_vertices)
    expected.push_back (v.getVector3fMap ());
  ASSERT_GT (expected.size (), 20u);
  EXPECT_EQ (sorted (convexHullVertices (points)), sorted (expected));
}

TEST (ConvexHullVertices, NoHullIsEmpty)
{
  EXPECT_TRUE (convexHullVertices ({}).empty ());
  EXPECT_TRUE (convexHullVertices ({Eigen::Vector3f (0, 0, 0), Eigen::Vector3f (1, 0, 0), Eigen::Vector3f (0, 1, 0)}).empty ());
  // All in a plane: qhull refuses (and says why on stderr, as under pcl::ConvexHull).
  EXPECT_TRUE (convexHullVertices ({Eigen::Vector3f (0, 0, 0), Eigen::Vector3f (1, 0, 0), Eigen::Vector3f (0, 1, 0),
                                    Eigen::Vector3f (1, 1, 0), Eigen::Vector3f (0.5f, 0.5f, 0)}).empty ());
}
