/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/surface/stray_fragment_removal.h>
#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>
#include "../common/union_find.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace pcl
{
  namespace
  {
    using Cell = Eigen::Matrix<std::int64_t, 3, 1>;

    struct CellHash
    {
      std::size_t
      operator() (const Cell& c) const
      {
        // Large odd multipliers spread neighbouring cells over the buckets.
        return static_cast<std::size_t> (c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL);
      }
    };
  }

  std::vector<bool>
  strayFragmentPoints (const pcl::PointCloud<pcl::PointNormal>& points, double gap, double max_fraction)
  {
    if (!(gap > 0.0) || !std::isfinite (gap))
      PCL_TENSOR_THROW (BadArgumentException, "stray fragments: the grouping distance must be positive and finite, got " << gap);
    if (!(max_fraction >= 0.0 && max_fraction < 1.0))
      PCL_TENSOR_THROW (BadArgumentException, "stray fragments: the fraction must be in [0, 1), got " << max_fraction);
    std::vector<bool> stray (points.size (), false);
    if (max_fraction == 0.0)
      return stray;

    // Cells relative to the first finite point, so that coordinates far from the origin keep their digits.
    const auto first = std::find_if (points.begin (), points.end (), [] (const pcl::PointNormal& p) { return pcl::isXYZFinite (p); });
    if (first == points.end ())
      return stray;
    const Eigen::Vector3d origin = first->getVector3fMap ().cast<double> ();
    std::unordered_map<Cell, std::size_t, CellHash> cell_ids;
    std::vector<Cell> cells;
    std::vector<std::size_t> cell_of (points.size (), 0);
    std::size_t finite = 0;
    for (std::size_t i = 0; i < points.size (); ++i)
    {
      if (!pcl::isXYZFinite (points[i]))
        continue;
      ++finite;
      const Cell c = ((points[i].getVector3fMap ().cast<double> () - origin) / gap).array ().floor ().cast<std::int64_t> ();
      const auto inserted = cell_ids.emplace (c, cells.size ());
      if (inserted.second)
        cells.push_back (c);
      cell_of[i] = inserted.first->second;
    }

    // Occupied cells that touch (26-neighbourhood) belong to one group.
    detail::UnionFind groups (cells.size ());
    for (std::size_t k = 0; k < cells.size (); ++k)
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz)
          {
            const auto n = cell_ids.find (cells[k] + Cell (dx, dy, dz));
            if (n != cell_ids.end ())
              groups.unite (n->second, k);
          }

    std::vector<std::size_t> group_size (cells.size (), 0);
    for (std::size_t i = 0; i < points.size (); ++i)
      if (pcl::isXYZFinite (points[i]))
        ++group_size[groups.find (cell_of[i])];
    // The largest group is the scan, however scattered it is: never all of it stray.
    const std::size_t largest = static_cast<std::size_t> (std::max_element (group_size.begin (), group_size.end ()) - group_size.begin ());
    const double min_points = max_fraction * static_cast<double> (finite);
    for (std::size_t i = 0; i < points.size (); ++i)
      if (pcl::isXYZFinite (points[i]))
      {
        const std::size_t group = groups.find (cell_of[i]);
        stray[i] = group != largest && static_cast<double> (group_size[group]) < min_points;
      }
    return stray;
  }

  std::size_t
  removeStrayFragments (ScanMesh& mesh, double gap, double max_fraction)
  {
    const std::vector<bool> stray = strayFragmentPoints (*mesh.cloud, gap, max_fraction);
    const std::size_t removed = static_cast<std::size_t> (std::count (stray.begin (), stray.end (), true));
    if (removed == 0)
      return 0;
    std::vector<pcl::index_t> new_index (stray.size (), -1);
    pcl::PointCloud<pcl::PointNormal>::Ptr kept (new pcl::PointCloud<pcl::PointNormal>);
    kept->reserve (stray.size () - removed);
    for (std::size_t i = 0; i < stray.size (); ++i)
      if (!stray[i])
      {
        new_index[i] = static_cast<pcl::index_t> (kept->size ());
        kept->push_back ((*mesh.cloud)[i]);
      }
    kept->is_dense = mesh.cloud->is_dense;
    std::vector<pcl::Vertices> polygons;
    polygons.reserve (mesh.polygons.size ());
    for (const auto& poly : mesh.polygons)
    {
      pcl::Vertices mapped;
      mapped.vertices.reserve (poly.vertices.size ());
      for (const auto v : poly.vertices)
        if (new_index[v] >= 0)
          mapped.vertices.push_back (new_index[v]);
      // A face is kept whole or not at all: a stray vertex's face has no kept vertex unless it spans
      // the gap, and such a face is dropped with the fragment.
      if (mapped.vertices.size () == poly.vertices.size ())
        polygons.push_back (std::move (mapped));
    }
    mesh.cloud = kept;
    mesh.polygons.swap (polygons);
    return removed;
  }
}
