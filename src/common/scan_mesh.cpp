/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/common/scan_mesh.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/conversions.h>

#include <algorithm>
#include <utility>

namespace pcl
{
  namespace
  {
    Eigen::Vector3d
    vertex (const ScanMesh& mesh, pcl::index_t i)
    {
      return (*mesh.cloud)[i].getVector3fMap ().cast<double> ();
    }

    /** Call \a visit (a, b, count) for every undirected edge {a, b} (a < b) of the mesh once, in
      * ascending (a, b) order, with the number of polygon sides on it (2 for an interior edge of a
      * manifold, 1 on the border). The edges are bucketed by their lower vertex and each bucket (a
      * vertex's valence) sorted on its own, which is much cheaper than one sort of every edge
      * (figures: doc/log.md). */
    template <typename Visit> void
    forEachEdge (const ScanMesh& mesh, Visit visit)
    {
      const std::size_t n = mesh.cloud->size ();
      const auto sides = [&mesh] (auto side) {
        for (const auto& poly : mesh.polygons)
          for (std::size_t k = 0; k < poly.vertices.size (); ++k)
          {
            const pcl::index_t a = poly.vertices[k], b = poly.vertices[(k + 1) % poly.vertices.size ()];
            side (std::min (a, b), std::max (a, b));
          }
      };
      std::vector<std::size_t> offsets (n + 1, 0);
      sides ([&] (pcl::index_t lo, pcl::index_t) { ++offsets[lo + 1]; });
      for (std::size_t v = 0; v < n; ++v)
        offsets[v + 1] += offsets[v];
      std::vector<pcl::index_t> higher (offsets[n]);
      std::vector<std::size_t> next (offsets.begin (), offsets.end () - 1);
      sides ([&] (pcl::index_t lo, pcl::index_t hi) { higher[next[lo]++] = hi; });
      for (std::size_t v = 0; v < n; ++v)
      {
        const auto first = higher.begin () + static_cast<std::ptrdiff_t> (offsets[v]);
        const auto last = higher.begin () + static_cast<std::ptrdiff_t> (offsets[v + 1]);
        std::sort (first, last);
        for (auto i = first; i != last;)
        {
          const auto j = std::find_if (i, last, [i] (pcl::index_t b) { return b != *i; });
          visit (static_cast<pcl::index_t> (v), *i, static_cast<std::size_t> (j - i));
          i = j;
        }
      }
    }
  }

  double
  meshResolution (const ScanMesh& mesh)
  {
    // Each interior edge is shared by two triangles; count it once.
    double sum = 0.0;
    std::size_t edges = 0;
    forEachEdge (mesh, [&] (pcl::index_t a, pcl::index_t b, std::size_t) {
      sum += (vertex (mesh, a) - vertex (mesh, b)).norm ();
      ++edges;
    });
    return edges ? sum / static_cast<double> (edges) : 0.0;
  }

  std::vector<bool>
  meshBoundaryVertices (const ScanMesh& mesh)
  {
    std::vector<bool> boundary (mesh.cloud->size (), false);
    forEachEdge (mesh, [&] (pcl::index_t a, pcl::index_t b, std::size_t sides) {
      if (sides == 1)
        boundary[a] = boundary[b] = true;
    });
    return boundary;
  }

  double
  meshArea (const ScanMesh& mesh)
  {
    double area = 0.0;
    for (const auto& poly : mesh.polygons)
    {
      const Eigen::Vector3d a = vertex (mesh, poly.vertices[0]);
      for (std::size_t k = 1; k + 1 < poly.vertices.size (); ++k)
        area += 0.5 * (vertex (mesh, poly.vertices[k]) - a).cross (vertex (mesh, poly.vertices[k + 1]) - a).norm ();
    }
    return area;
  }

  void
  toPolygonMesh (const ScanMesh& mesh, pcl::PolygonMesh& out)
  {
    pcl::toPCLPointCloud2 (*mesh.cloud, out.cloud);
    out.polygons = mesh.polygons;
  }

  void
  fromPolygonMesh (const pcl::PolygonMesh& in, ScanMesh& out)
  {
    const std::size_t n = static_cast<std::size_t> (in.cloud.width) * in.cloud.height;
    if (n == 0 && !in.polygons.empty ())
      PCL_TENSOR_THROW (InvalidScanException, "mesh has " << in.polygons.size () << " faces but no vertices");
    out.cloud.reset (new pcl::PointCloud<pcl::PointNormal>);
    pcl::fromPCLPointCloud2 (in.cloud, *out.cloud);
    out.polygons.clear ();
    out.polygons.reserve (in.polygons.size ());
    for (const auto& poly : in.polygons)
    {
      for (const auto idx : poly.vertices)
        if (idx < 0 || static_cast<std::size_t> (idx) >= n)
          PCL_TENSOR_THROW (InvalidScanException, "face refers to vertex " << idx << " of " << n);
      for (std::size_t k = 1; k + 1 < poly.vertices.size (); ++k)
      {
        pcl::Vertices tri;
        tri.vertices = {poly.vertices[0], poly.vertices[k], poly.vertices[k + 1]};
        out.polygons.push_back (std::move (tri));
      }
    }
  }
}
