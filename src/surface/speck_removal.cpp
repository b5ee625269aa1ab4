/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/surface/speck_removal.h>
#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>
#include "../common/union_find.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace pcl
{
  namespace
  {
    /** One image's grid: its points as doubles and which of them are finite. */
    struct PixelGrid
    {
      explicit PixelGrid (const pcl::PointCloud<pcl::PointXYZ>& cloud)
        : width (static_cast<int> (cloud.width)), height (static_cast<int> (cloud.height)),
          points (cloud.size ()), finite (cloud.size (), false)
      {
        for (std::size_t i = 0; i < cloud.size (); ++i)
        {
          finite[i] = pcl::isXYZFinite (cloud[i]);
          if (finite[i])
            points[i] = cloud[i].getVector3fMap ().cast<double> ();
        }
      }

      /** The pixel at row \a r and column \a c, or -1 outside the image or where it is empty. */
      long
      at (int r, int c) const
      {
        if (r < 0 || c < 0 || r >= height || c >= width)
          return -1;
        const auto i = static_cast<std::size_t> (r) * static_cast<std::size_t> (width) + static_cast<std::size_t> (c);
        return finite[i] ? static_cast<long> (i) : -1;
      }

      int width, height;
      std::vector<Eigen::Vector3d> points;
      std::vector<bool> finite;
    };

    /** The median distance between finite 4-neighbours: the grid's spacing on the surface. */
    double
    gridSpacing (const PixelGrid& grid)
    {
      std::vector<double> d;
      for (int r = 0; r < grid.height; ++r)
        for (int c = 0; c < grid.width; ++c)
          if (const long i = grid.at (r, c); i >= 0)
            for (const long j : {grid.at (r, c + 1), grid.at (r + 1, c)})
              if (j >= 0)
                d.push_back ((grid.points[i] - grid.points[j]).norm ());
      if (d.empty ())
        return 0.0;
      std::nth_element (d.begin (), d.begin () + d.size () / 2, d.end ());
      return d[d.size () / 2];
    }

    /** The 8 neighbours of a pixel, as row and column offsets. */
    constexpr int kNeighbours[8][2] = {{-1, -1}, {-1, 0}, {-1, 1}, {0, -1}, {0, 1}, {1, -1}, {1, 0}, {1, 1}};

    /** True when group \a g is surrounded by surface behind it: every neighbour of its pixels outside
      * it is a return that lies behind them. An empty neighbour (the image's edge, a hole, dropout at
      * a silhouette) may hide the surface it belongs to, so the group is not a speck. */
    bool
    standsInFront (const PixelGrid& grid, const std::vector<long>& members, std::size_t g, detail::UnionFind& groups,
                   const ScanViewpoint& viewpoint)
    {
      for (const long i : members)
      {
        const int r = static_cast<int> (i / grid.width), c = static_cast<int> (i % grid.width);
        const Eigen::Vector3d away = -viewpoint.towardSensor (grid.points[i]);
        for (const auto& n : kNeighbours)
        {
          const long j = grid.at (r + n[0], c + n[1]);
          if (j < 0)
            return false;
          if (groups.find (static_cast<std::size_t> (j)) == g)
            continue;
          const Eigen::Vector3d step = grid.points[j] - grid.points[i];
          // Behind: the step runs within 60 degrees of the line of sight, away from the sensor.
          if (step.dot (away) <= 0.5 * step.norm ())
            return false;
        }
      }
      return true;
    }
  }

  void
  checkSpeckParameters (int max_pixels, double jump)
  {
    if (max_pixels < 0 || !(jump > 0.0) || !std::isfinite (jump))
      PCL_TENSOR_THROW (BadArgumentException, "specks: the size must be non-negative and the jump positive and finite, got "
                        << max_pixels << " and " << jump);
  }

  std::vector<bool>
  speckPixels (const pcl::PointCloud<pcl::PointXYZ>& cloud, const ScanViewpoint& viewpoint, int max_pixels, double jump)
  {
    checkSpeckParameters (max_pixels, jump);
    std::vector<bool> speck (cloud.size (), false);
    if (max_pixels == 0 || !cloud.isOrganized ())
      return speck;
    const PixelGrid grid (cloud);
    const double link = jump * gridSpacing (grid);
    if (!(link > 0.0))
      return speck;

    // Neighbours within the link distance share a group; each pair is looked at once.
    detail::UnionFind groups (cloud.size ());
    for (int r = 0; r < grid.height; ++r)
      for (int c = 0; c < grid.width; ++c)
        if (const long i = grid.at (r, c); i >= 0)
          for (const long j : {grid.at (r, c + 1), grid.at (r + 1, c - 1), grid.at (r + 1, c), grid.at (r + 1, c + 1)})
            if (j >= 0 && (grid.points[i] - grid.points[j]).norm () <= link)
              groups.unite (static_cast<std::size_t> (j), static_cast<std::size_t> (i));

    std::vector<std::size_t> size (cloud.size (), 0);
    for (std::size_t i = 0; i < cloud.size (); ++i)
      if (grid.finite[i])
        ++size[groups.find (i)];
    // The small groups' pixels, by group; a scan has few of them.
    std::map<std::size_t, std::vector<long>> small;
    for (std::size_t i = 0; i < cloud.size (); ++i)
      if (grid.finite[i] && size[groups.find (i)] <= static_cast<std::size_t> (max_pixels))
        small[groups.find (i)].push_back (static_cast<long> (i));
    for (const auto& [g, members] : small)
      if (standsInFront (grid, members, g, groups, viewpoint))
        for (const long i : members)
          speck[static_cast<std::size_t> (i)] = true;
    return speck;
  }

  std::size_t
  removeSpecks (pcl::PointCloud<pcl::PointXYZ>& cloud, const ScanViewpoint& viewpoint, int max_pixels, double jump)
  {
    return removeSpecks (cloud, speckPixels (cloud, viewpoint, max_pixels, jump));
  }

  std::size_t
  removeSpecks (pcl::PointCloud<pcl::PointXYZ>& cloud, const std::vector<bool>& speck)
  {
    const float nan = std::numeric_limits<float>::quiet_NaN ();
    std::size_t removed = 0;
    for (std::size_t i = 0; i < speck.size (); ++i)
      if (speck[i])
      {
        cloud[i].x = cloud[i].y = cloud[i].z = nan;
        ++removed;
      }
    if (removed > 0)
      cloud.is_dense = false;
    return removed;
  }
}
