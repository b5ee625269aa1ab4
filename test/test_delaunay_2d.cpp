/*
 * The retinal plane's Delaunay triangulation (src/surface/delaunay_2d.h) against its definition:
 * no point inside any triangle's circumcircle, the triangles tile the convex hull, and Euler's count.
 */
#include "surface/delaunay_2d.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

namespace
{
  using Points = std::vector<Eigen::Vector2d>;
  using pcl::detail::delaunayTriangulation;

  double
  signedArea (const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c)
  {
    const Eigen::Vector2d e1 = b - a, e2 = c - a;
    return 0.5 * (e1.x () * e2.y () - e1.y () * e2.x ());
  }

  /** The convex hull's area and the number of points on its boundary, corners and points along its
    * edges alike (Andrew's monotone chain keeping collinear points): Euler's count needs them all. */
  std::pair<double, std::size_t>
  convexHull (Points p)
  {
    std::sort (p.begin (), p.end (), [] (const auto& a, const auto& b) { return a.x () < b.x () || (a.x () == b.x () && a.y () < b.y ()); });
    p.erase (std::unique (p.begin (), p.end ()), p.end ());
    Points hull (2 * p.size ());
    std::size_t k = 0;
    for (std::size_t i = 0; i < p.size (); ++i)
    {
      while (k >= 2 && signedArea (hull[k - 2], hull[k - 1], p[i]) < 0.0)
        --k;
      hull[k++] = p[i];
    }
    for (std::size_t i = p.size () - 1, t = k + 1; i > 0; --i)
    {
      while (k >= t && signedArea (hull[k - 2], hull[k - 1], p[i - 1]) < 0.0)
        --k;
      hull[k++] = p[i - 1];
    }
    hull.resize (k - 1);
    double area = 0.0;
    for (std::size_t i = 1; i + 1 < hull.size (); ++i)
      area += signedArea (hull[0], hull[i], hull[i + 1]);
    return {area, hull.size ()};
  }

  /** Checks every defining property of the triangulation of \a p (distinct points). */
  void
  expectDelaunay (const Points& p)
  {
    const auto triangles = delaunayTriangulation (p);
    const auto [hull_area, hull_size] = convexHull (p);
    EXPECT_EQ (triangles.size (), 2 * p.size () - 2 - hull_size) << "Euler: 2n - 2 - h triangles";
    double area = 0.0;
    std::set<std::pair<int, int>> edges;
    for (const auto& t : triangles)
    {
      const double a = signedArea (p[t[0]], p[t[1]], p[t[2]]);
      ASSERT_GT (a, 0.0) << "counter-clockwise";
      area += a;
      for (int k = 0; k < 3; ++k)
        EXPECT_TRUE (edges.insert ({t[k], t[(k + 1) % 3]}).second) << "each directed edge once: no overlap";
      // Empty circumcircle, with a tolerance for points on it.
      const Eigen::Vector2d d = p[t[1]] - p[t[0]], e = p[t[2]] - p[t[0]];
      const double k2 = 0.5 / (d.x () * e.y () - d.y () * e.x ());
      const Eigen::Vector2d centre = p[t[0]] + Eigen::Vector2d ((e.y () * d.squaredNorm () - d.y () * e.squaredNorm ()) * k2,
                                                               (d.x () * e.squaredNorm () - e.x () * d.squaredNorm ()) * k2);
      const double r2 = (p[t[0]] - centre).squaredNorm ();
      for (std::size_t i = 0; i < p.size (); ++i)
        ASSERT_GE ((p[i] - centre).squaredNorm (), r2 * (1.0 - 1e-9)) << "point " << i << " inside a circumcircle";
    }
    EXPECT_NEAR (area, hull_area, 1e-9 * hull_area) << "the triangles tile the hull";
  }
}

TEST (DelaunayTriangulation, RandomPointsAreDelaunay)
{
  for (const std::uint32_t seed : {1u, 2u, 3u})
  {
    std::mt19937 rng (seed);
    std::uniform_real_distribution<double> u (-1.0, 1.0);
    Points p (400);
    for (auto& q : p)
      q = Eigen::Vector2d (u (rng), u (rng));
    SCOPED_TRACE (seed);
    expectDelaunay (p);
  }
}

TEST (DelaunayTriangulation, AGridOfCocircularPointsIsTiledWhole)
{
  // Every square's four corners lie on one circle: any diagonal is Delaunay, none may be left out.
  Points p;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 25; ++x)
      p.emplace_back (0.01 * x, 0.01 * y);
  expectDelaunay (p);
}

TEST (DelaunayTriangulation, ClusteredPointsFarFromTheOriginAreDelaunay)
{
  // A scan's retinal coordinates: dense, uneven, offset.
  std::mt19937 rng (7);
  std::normal_distribution<double> g (0.0, 1.0);
  Points p (600);
  for (std::size_t i = 0; i < p.size (); ++i)
    p[i] = Eigen::Vector2d (1000.0 + (i % 2 ? 0.01 : 0.1) * g (rng), -500.0 + 0.05 * g (rng));
  expectDelaunay (p);
}

TEST (DelaunayTriangulation, DuplicatesAreLeftOutAndCollinearPointsGiveNothing)
{
  Points p{{0, 0}, {1, 0}, {0, 1}, {1, 1}, {1, 1}, {0, 0}};
  const auto triangles = delaunayTriangulation (p);
  EXPECT_EQ (triangles.size (), 2u);
  std::set<int> used;
  for (const auto& t : triangles)
    used.insert (t.begin (), t.end ());
  EXPECT_EQ (used.size (), 4u) << "each place once";

  EXPECT_TRUE (delaunayTriangulation ({{0, 0}, {1, 1}, {2, 2}, {3, 3}}).empty ());
  EXPECT_TRUE (delaunayTriangulation ({{0, 0}, {1, 1}}).empty ());
  EXPECT_TRUE (delaunayTriangulation ({}).empty ());
  EXPECT_EQ (delaunayTriangulation ({{0, 0}, {1, 0}, {0, 1}}).size (), 1u);
}
