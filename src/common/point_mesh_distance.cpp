/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/common/point_mesh_distance.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/kdtree/kdtree_flann.h>

#include <algorithm>
#include <array>
#include <limits>

namespace pcl
{
  double
  pointTriangleDistance (const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c)
  {
    // Ericson, Real-Time Collision Detection, 5.1.5: closest point on a triangle by Voronoi regions.
    const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot (ap), d2 = ac.dot (ap);
    if (d1 <= 0.0 && d2 <= 0.0)
      return ap.norm ();
    const Eigen::Vector3d bp = p - b;
    const double d3 = ab.dot (bp), d4 = ac.dot (bp);
    if (d3 >= 0.0 && d4 <= d3)
      return bp.norm ();
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
      return (p - (a + d1 / (d1 - d3) * ab)).norm ();
    const Eigen::Vector3d cp = p - c;
    const double d5 = ab.dot (cp), d6 = ac.dot (cp);
    if (d6 >= 0.0 && d5 <= d6)
      return cp.norm ();
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
      return (p - (a + d2 / (d2 - d6) * ac)).norm ();
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
      return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm ();
    const double denom = va + vb + vc;
    // A degenerate (zero-area) triangle reaches here only through its edges' cases; guard anyway.
    if (denom == 0.0)
      return std::min ({ap.norm (), bp.norm (), cp.norm ()});
    return (p - (a + ab * (vb / denom) + ac * (vc / denom))).norm ();
  }

  struct PointMeshDistance::Index
  {
    std::vector<Eigen::Vector3d> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    pcl::KdTreeFLANN<pcl::PointXYZ> vertex_tree;
    pcl::KdTreeFLANN<pcl::PointXYZ> centroid_tree;
    double max_reach = 0.0;  ///< largest distance from a triangle's centroid to its vertices
  };

  PointMeshDistance::PointMeshDistance () = default;
  PointMeshDistance::~PointMeshDistance () = default;

  void
  PointMeshDistance::setMesh (const ScanMesh& mesh)
  {
    if (mesh.polygons.empty ())
      PCL_TENSOR_THROW (InvalidScanException, "PointMeshDistance: the mesh has no triangles");
    auto index = std::make_unique<Index> ();
    pcl::PointCloud<pcl::PointXYZ>::Ptr vertices (new pcl::PointCloud<pcl::PointXYZ>);
    pcl::PointCloud<pcl::PointXYZ>::Ptr centroids (new pcl::PointCloud<pcl::PointXYZ>);
    for (const auto& p : *mesh.cloud)
    {
      index->vertices.push_back (p.getVector3fMap ().cast<double> ());
      vertices->push_back (pcl::PointXYZ (p.x, p.y, p.z));
    }
    for (const auto& poly : mesh.polygons)
    {
      if (poly.vertices.size () != 3)
        PCL_TENSOR_THROW (InvalidScanException, "PointMeshDistance: a polygon is not a triangle");
      std::array<std::uint32_t, 3> t;
      for (int k = 0; k < 3; ++k)
      {
        if (poly.vertices[k] < 0 || static_cast<std::size_t> (poly.vertices[k]) >= vertices->size ())
          PCL_TENSOR_THROW (InvalidScanException, "PointMeshDistance: vertex index " << poly.vertices[k]
                            << " out of range (" << vertices->size () << " vertices)");
        t[k] = static_cast<std::uint32_t> (poly.vertices[k]);
      }
      const Eigen::Vector3d g = (index->vertices[t[0]] + index->vertices[t[1]] + index->vertices[t[2]]) / 3.0;
      for (auto v : t)
        index->max_reach = std::max (index->max_reach, (index->vertices[v] - g).norm ());
      index->triangles.push_back (t);
      pcl::PointXYZ c;
      c.getVector3fMap () = g.cast<float> ();
      centroids->push_back (c);
    }
    index->vertex_tree.setInputCloud (vertices);
    index->centroid_tree.setInputCloud (centroids);
    index_ = std::move (index);
  }

  double
  PointMeshDistance::distance (const Eigen::Vector3d& p) const
  {
    if (!index_)
      PCL_TENSOR_THROW (InvalidScanException, "PointMeshDistance::distance: no mesh was set");
    pcl::PointXYZ q;
    q.getVector3fMap () = p.cast<float> ();
    pcl::Indices nn (1);
    std::vector<float> sq (1);
    index_->vertex_tree.nearestKSearch (q, 1, nn, sq);
    const double vertex_distance = (index_->vertices[nn[0]] - p).norm ();
    // Centroids are stored as floats: a small absolute margin covers their rounding.
    const double radius = vertex_distance + index_->max_reach + 1e-6 * (1.0 + p.norm ());
    pcl::Indices candidates;
    std::vector<float> cand_sq;
    index_->centroid_tree.radiusSearch (q, radius, candidates, cand_sq);
    double best = vertex_distance;
    for (const auto t : candidates)
    {
      const auto& tri = index_->triangles[t];
      best = std::min (best, pointTriangleDistance (p, index_->vertices[tri[0]], index_->vertices[tri[1]],
                                                    index_->vertices[tri[2]]));
    }
    return best;
  }
}
