/*
 * pcl_tensor: tests of the bounded nearest-neighbour grid search.
 */
#include "test_utils.h"

#include <pcl/search/bounded_nearest_search.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/kdtree/kdtree_flann.h>

#include <limits>
#include <random>

namespace
{
  /** The nearest of \a points within \a radius of \a q by brute force, lower index on ties; -1 if none. */
  int
  bruteNearest (const std::vector<Eigen::Vector3f>& points, const Eigen::Vector3f& q, float radius, float& best)
  {
    best = radius * radius;
    int index = -1;
    for (std::size_t i = 0; i < points.size (); ++i)
    {
      if (!points[i].allFinite ())
        continue;
      const float dx = points[i].x () - q.x (), dy = points[i].y () - q.y (), dz = points[i].z () - q.z ();
      const float d2 = dx * dx + dy * dy + dz * dz;
      if (d2 < best || (d2 == best && index < 0))
      {
        best = d2;
        index = static_cast<int> (i);
      }
    }
    return index;
  }

  /** Points on a wavy sheet z = 0.1 sin(7x) cos(5y), like a range view's surface, plus noise. */
  std::vector<Eigen::Vector3f>
  wavySheet (std::size_t n, unsigned seed)
  {
    std::mt19937 rng (seed);
    std::uniform_real_distribution<float> u (-1.0f, 1.0f);
    std::normal_distribution<float> noise (0.0f, 0.002f);
    std::vector<Eigen::Vector3f> points (n);
    for (auto& p : points)
    {
      const float x = u (rng), y = u (rng);
      p = Eigen::Vector3f (x, y, 0.1f * std::sin (7.0f * x) * std::cos (5.0f * y) + noise (rng));
    }
    return points;
  }
}

// Known answers on a lattice: every query's nearest point and distance are exact.
TEST (BoundedNearestSearch, LatticeKnownAnswers)
{
  std::vector<Eigen::Vector3f> lattice;
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x)
        lattice.emplace_back (static_cast<float> (x), static_cast<float> (y), static_cast<float> (z));
  pcl::BoundedNearestSearch search (1.0f);
  search.setPoints (lattice);
  ASSERT_EQ (search.size (), 64u);
  float d2 = -1.0f;
  // (1.25, 2, 3) is nearest to (1, 2, 3), index 1 + 4 * 2 + 16 * 3 = 57, at 0.25.
  EXPECT_EQ (search.nearest ({1.25f, 2.0f, 3.0f}, 0.5f, d2), 57);
  EXPECT_FLOAT_EQ (d2, 0.0625f);
  // Halfway between (1, 2, 3) and (2, 2, 3): a tie, the lower index wins.
  EXPECT_EQ (search.nearest ({1.5f, 2.0f, 3.0f}, 0.5f, d2), 57);
  // The radius is inclusive ...
  EXPECT_TRUE (search.anyWithin ({1.5f, 2.0f, 3.0f}, 0.5f));
  // ... and nothing beyond it is returned.
  EXPECT_EQ (search.nearest ({1.5f, 2.5f, 3.0f}, 0.5f, d2), -1);
  EXPECT_FALSE (search.anyWithin ({1.5f, 2.5f, 3.0f}, 0.5f));
  // Outside the grid's bounding box, but within reach of its corner (3, 3, 3) = index 63.
  EXPECT_EQ (search.nearest ({3.0f, 3.0f, 4.5f}, 2.0f, d2), 63);
  EXPECT_FLOAT_EQ (d2, 2.25f);
  EXPECT_EQ (search.nearest ({3.0f, 3.0f, 10.0f}, 2.0f, d2), -1);
  // A radius far larger than a cell scans more cells and stays exact.
  EXPECT_EQ (search.nearest ({-5.0f, 0.0f, 0.0f}, 6.0f, d2), 0);
  EXPECT_FLOAT_EQ (d2, 25.0f);
  // A wide radius is answered from half a cell first: the tie at exactly that distance still goes to
  // the lower index, and a nearest point just beyond it is found by the wide scan.
  EXPECT_EQ (search.nearest ({1.5f, 2.0f, 3.0f}, 5.0f, d2), 57);
  EXPECT_FLOAT_EQ (d2, 0.25f);
  EXPECT_EQ (search.nearest ({1.5f, 2.5f, 3.0f}, 5.0f, d2), 57);
  EXPECT_FLOAT_EQ (d2, 0.5f);
  EXPECT_EQ (search.nearest ({1.5f, 2.5f, 3.5f}, 5.0f, d2), 57);
  EXPECT_FLOAT_EQ (d2, 0.75f);
}

// Successive queries along a line, as a view's points come: the hint answers most of them, and
// every answer is the one without it.
TEST (BoundedNearestSearch, HintedRunsAnswerAsWithout)
{
  const auto points = wavySheet (20000, 4);
  const float spacing = 2.0f / std::sqrt (20000.0f);
  pcl::BoundedNearestSearch search (2.0f * spacing);
  search.setPoints (points);
  std::int32_t hint = -1;
  std::size_t within = 0;
  for (int k = 0; k < 4000; ++k)
  {
    const float x = -1.0f + 2.0f * static_cast<float> (k) / 4000.0f, y = 0.3f;
    const float z = 0.1f * std::sin (7.0f * x) * std::cos (5.0f * y) + (k % 7 == 0 ? 4.0f * spacing : 0.0f);
    const Eigen::Vector3f q (x, y, z);
    const bool expected = search.anyWithin (q, spacing);
    ASSERT_EQ (search.anyWithin (q, spacing, hint), expected) << "query " << k;
    within += expected ? 1 : 0;
  }
  // Both answers occur: the points off the sheet (every 7th) have no neighbour that near.
  EXPECT_GT (within, 2000u);
  EXPECT_LT (within, 3800u);
}

// ICP's queries: the same points moved a little each iteration, each starting from its last answer.
// Ties (duplicated points) and queries that leave the radius are included; every answer is brute force's.
TEST (BoundedNearestSearch, HintedNearestAnswersAsBruteForce)
{
  auto points = wavySheet (20000, 5);
  for (std::size_t i = 0; i < 2000; ++i)
    points.push_back (points[7 * i]);  // exact duplicates with higher indices: ties to break
  const float spacing = 2.0f / std::sqrt (20000.0f);
  pcl::BoundedNearestSearch search (2.0f * spacing);
  search.setPoints (points);
  std::mt19937 rng (11);
  std::uniform_int_distribution<std::size_t> pick (0, 19999);
  std::normal_distribution<float> jitter (0.0f, spacing);
  std::vector<Eigen::Vector3f> queries (1500);
  for (auto& q : queries)
    q = points[pick (rng)] + Eigen::Vector3f (jitter (rng), jitter (rng), jitter (rng));
  std::vector<std::int32_t> hints (queries.size (), -1);
  const float radius = 3.0f * spacing;
  std::size_t found = 0, missed = 0, hinted = 0;
  for (int it = 0; it < 6; ++it)
  {
    // A shrinking rigid step: a turn about z and a shift, as a converging ICP makes.
    const float angle = 0.02f / static_cast<float> (1 << it);
    const Eigen::Affine3f step = Eigen::Translation3f (0.5f * spacing, -0.3f * spacing, 0.2f * spacing)
                                 * Eigen::AngleAxisf (angle, Eigen::Vector3f::UnitZ ());
    for (std::size_t k = 0; k < queries.size (); ++k)
    {
      queries[k] = step * queries[k];
      hinted += hints[k] >= 0 ? 1 : 0;
      float brute_d2 = 0.0f, d2 = -1.0f;
      const int expected = bruteNearest (points, queries[k], radius, brute_d2);
      ASSERT_EQ (search.nearest (queries[k], radius, d2, hints[k]), expected) << "iteration " << it << ", query " << k;
      if (expected >= 0)
      {
        ASSERT_EQ (pcl_tensor_test::bits (d2), pcl_tensor_test::bits (brute_d2)) << "iteration " << it << ", query " << k;
      }
      found += expected >= 0 ? 1 : 0;
      missed += expected < 0 ? 1 : 0;
    }
  }
  // Most searches started from a hint, and both outcomes occurred.
  EXPECT_GT (hinted, queries.size () * 4);
  EXPECT_GT (found, queries.size () * 4);
  EXPECT_GT (missed, 0u);
}

// Queries near a surface, with radii many cells wide, as a converging ICP asks them: the answer
// found within half a cell is the nearest one of the whole radius.
TEST (BoundedNearestSearch, NearSurfaceQueriesWithWideRadiiMatchBruteForce)
{
  const auto points = wavySheet (20000, 3);
  const float spacing = 2.0f / std::sqrt (20000.0f);
  pcl::BoundedNearestSearch search (2.0f * spacing);
  search.setPoints (points);
  std::mt19937 rng (9);
  std::uniform_real_distribution<float> u (-0.9f, 0.9f), h (-1.0f, 1.0f);
  for (int k = 0; k < 2000; ++k)
  {
    const float x = u (rng), y = u (rng);
    // Up to 2 spacings off the sheet: within half a cell for some queries, beyond it for others.
    const Eigen::Vector3f q (x, y, 0.1f * std::sin (7.0f * x) * std::cos (5.0f * y) + 2.0f * spacing * h (rng));
    const float radius = spacing * (k % 2 == 0 ? 8.0f : 3.0f);
    float brute_d2 = 0.0f, d2 = -1.0f;
    ASSERT_EQ (search.nearest (q, radius, d2), bruteNearest (points, q, radius, brute_d2)) << "query " << k;
    EXPECT_EQ (d2, brute_d2) << "query " << k;
  }
}

// Against brute force and PCL's kd-tree on a noisy sheet, at the radii verification uses.
TEST (BoundedNearestSearch, MatchesBruteForceAndKdTree)
{
  const auto points = wavySheet (20000, 11);
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : points)
    cloud->push_back ({p.x (), p.y (), p.z ()});
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud (cloud);
  const float spacing = 2.0f / std::sqrt (20000.0f);
  pcl::BoundedNearestSearch search (2.0f * spacing);
  search.setInputCloud (*cloud);
  ASSERT_EQ (search.size (), points.size ());

  std::mt19937 rng (5);
  std::uniform_real_distribution<float> u (-1.1f, 1.1f), h (-0.2f, 0.2f);
  std::size_t found = 0, missed = 0;
  std::int32_t hint = -1;  // carried from query to query, as a count along a view does
  for (int k = 0; k < 3000; ++k)
  {
    const Eigen::Vector3f q (u (rng), u (rng), h (rng));
    const float radius = spacing * (k % 3 == 0 ? 1.0f : k % 3 == 1 ? 4.0f : 6.0f);
    float brute_d2 = 0.0f, d2 = -1.0f;
    const int brute = bruteNearest (points, q, radius, brute_d2);
    const int got = search.nearest (q, radius, d2);
    ASSERT_EQ (got, brute) << "query " << k;
    EXPECT_EQ (search.anyWithin (q, radius), brute >= 0) << "query " << k;
    EXPECT_EQ (search.anyWithin (q, radius, hint), brute >= 0) << "query " << k;
    if (got < 0)
    {
      ++missed;
      continue;
    }
    ++found;
    EXPECT_EQ (d2, brute_d2);
    pcl::Indices index (1);
    std::vector<float> tree_d2 (1);
    ASSERT_EQ (tree.nearestKSearch (pcl::PointXYZ (q.x (), q.y (), q.z ()), 1, index, tree_d2), 1);
    EXPECT_EQ (d2, tree_d2[0]) << "query " << k;
  }
  // Both outcomes were exercised.
  EXPECT_GT (found, 300u);
  EXPECT_GT (missed, 300u);
}

// Non-finite points are never answered but keep their indices; non-finite queries find nothing.
TEST (BoundedNearestSearch, NonFiniteInputAndQueries)
{
  const float nan = std::numeric_limits<float>::quiet_NaN ();
  pcl::BoundedNearestSearch search (0.5f);
  search.setPoints ({{nan, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, std::numeric_limits<float>::infinity (), 0}});
  EXPECT_EQ (search.size (), 2u);
  float d2 = -1.0f;
  EXPECT_EQ (search.nearest ({0.9f, 0, 0}, 0.5f, d2), 2);
  EXPECT_EQ (search.nearest ({0.1f, 0, 0}, 0.5f, d2), 1);
  EXPECT_EQ (search.nearest ({nan, 0, 0}, 0.5f, d2), -1);
  EXPECT_FALSE (search.anyWithin ({0, 0, nan}, 10.0f));
  EXPECT_EQ (search.nearest ({0, 0, 0}, -1.0f, d2), -1);

  pcl::BoundedNearestSearch empty (1.0f);
  empty.setPoints ({{nan, nan, nan}});
  EXPECT_EQ (empty.size (), 0u);
  EXPECT_EQ (empty.nearest ({0, 0, 0}, 1.0f, d2), -1);
  EXPECT_THROW (pcl::BoundedNearestSearch (0.0f), pcl::BadArgumentException);
  EXPECT_THROW (pcl::BoundedNearestSearch {std::numeric_limits<float>::infinity ()}, pcl::BadArgumentException);
}

// Two clusters far apart would need a huge dense grid at the asked cell: the cells grow, the
// memory stays bounded by the point count, and the answers stay exact.
TEST (BoundedNearestSearch, SparseBoxGrowsTheCellsAndStaysExact)
{
  std::vector<Eigen::Vector3f> points = wavySheet (500, 2);
  for (std::size_t i = 0; i < 500; ++i)
    points.push_back (points[i] + Eigen::Vector3f (1000.0f, -1000.0f, 500.0f));
  pcl::BoundedNearestSearch search (0.01f);
  search.setPoints (points);
  EXPECT_GT (search.getCellSize (), 0.01f);
  std::mt19937 rng (9);
  std::uniform_real_distribution<float> u (-1.0f, 1.0f);
  for (int k = 0; k < 400; ++k)
  {
    const Eigen::Vector3f q = Eigen::Vector3f (u (rng), u (rng), 0.1f * u (rng)) +
                              (k % 2 ? Eigen::Vector3f (1000.0f, -1000.0f, 500.0f) : Eigen::Vector3f::Zero ());
    float brute_d2 = 0.0f, d2 = -1.0f;
    ASSERT_EQ (search.nearest (q, 0.1f, d2), bruteNearest (points, q, 0.1f, brute_d2)) << k;
  }
}
