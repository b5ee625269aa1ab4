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

    /** Every triangle's edges as (low, high) vertex pairs, sorted: an interior edge appears twice. */
    std::vector<std::pair<pcl::index_t, pcl::index_t>>
    sortedEdges (const ScanMesh& mesh)
    {
      std::vector<std::pair<pcl::index_t, pcl::index_t>> edges;
      edges.reserve (mesh.polygons.size () * 3);
      for (const auto& poly : mesh.polygons)
        for (std::size_t k = 0; k < poly.vertices.size (); ++k)
        {
          const pcl::index_t a = poly.vertices[k], b = poly.vertices[(k + 1) % poly.vertices.size ()];
          edges.emplace_back (std::min (a, b), std::max (a, b));
        }
      std::sort (edges.begin (), edges.end ());
      return edges;
    }
  }

  double
  meshResolution (const ScanMesh& mesh)
  {
    // Each interior edge is shared by two triangles; count it once.
    std::vector<std::pair<pcl::index_t, pcl::index_t>> edges = sortedEdges (mesh);
    edges.erase (std::unique (edges.begin (), edges.end ()), edges.end ());
    if (edges.empty ())
      return 0.0;
    double sum = 0.0;
    for (const auto& e : edges)
      sum += (vertex (mesh, e.first) - vertex (mesh, e.second)).norm ();
    return sum / static_cast<double> (edges.size ());
  }

  std::vector<bool>
  meshBoundaryVertices (const ScanMesh& mesh)
  {
    const std::vector<std::pair<pcl::index_t, pcl::index_t>> edges = sortedEdges (mesh);
    std::vector<bool> boundary (mesh.cloud->size (), false);
    for (std::size_t i = 0; i < edges.size ();)
    {
      std::size_t j = i + 1;
      while (j < edges.size () && edges[j] == edges[i])
        ++j;
      if (j - i == 1)
        boundary[edges[i].first] = boundary[edges[i].second] = true;
      i = j;
    }
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
