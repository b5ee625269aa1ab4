/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/surface/quadric_mesh_reduction.h>
#include <pcl/common/tensor_exceptions.h>
#include "../common/union_find.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <map>
#include <limits>

namespace pcl
{
  namespace
  {
    /** Build a mesh from a flat triangle index list, keeping only the vertices some triangle uses.
      * Duplicated and zero-area triangles are dropped: collapses along a straight border leave slivers whose
      * three vertices are collinear, and their rounding-noise normals would spoil vertex normals. */
    void
    compactMesh (const std::vector<unsigned int>& indices, const pcl::PointCloud<pcl::PointNormal>& vertices, ScanMesh& out)
    {
      // Scale-free test: the triangle's height over its longest edge is at the level of float rounding.
      auto is_sliver = [&] (std::size_t t) {
        const Eigen::Vector3d a = vertices[indices[t]].getVector3fMap ().cast<double> ();
        const Eigen::Vector3d b = vertices[indices[t + 1]].getVector3fMap ().cast<double> ();
        const Eigen::Vector3d c = vertices[indices[t + 2]].getVector3fMap ().cast<double> ();
        const double longest2 = std::max ({(b - a).squaredNorm (), (c - b).squaredNorm (), (a - c).squaredNorm ()});
        return (b - a).cross (c - a).norm () <= 1e-6 * longest2;
      };

      // A triangle present twice (once per winding) is a fold that encloses nothing; both copies
      // go, or their normals would cancel at the vertices (seen on bun270).
      auto key = [&] (std::size_t t) {
        std::array<unsigned int, 3> k{indices[t], indices[t + 1], indices[t + 2]};
        std::sort (k.begin (), k.end ());
        return k;
      };
      std::map<std::array<unsigned int, 3>, int> copies;
      for (std::size_t t = 0; t + 2 < indices.size (); t += 3)
        ++copies[key (t)];

      std::vector<pcl::index_t> vertex_of (vertices.size (), -1);
      out.cloud.reset (new pcl::PointCloud<pcl::PointNormal>);
      out.polygons.clear ();
      out.polygons.reserve (indices.size () / 3);
      for (std::size_t t = 0; t + 2 < indices.size (); t += 3)
      {
        if (is_sliver (t) || copies[key (t)] > 1)
          continue;
        pcl::Vertices tri;
        for (std::size_t k = 0; k < 3; ++k)
        {
          const std::size_t id = indices[t + k];
          if (vertex_of[id] < 0)
          {
            pcl::PointNormal p = vertices[id];
            p.getNormalVector3fMap ().setZero ();
            p.curvature = 0.0f;
            vertex_of[id] = static_cast<pcl::index_t> (out.cloud->size ());
            out.cloud->push_back (p);
          }
          tri.vertices.push_back (vertex_of[id]);
        }
        out.polygons.push_back (std::move (tri));
      }
      out.cloud->is_dense = true;
    }

    /** The triangles whose vertex-connected component has at least \a min_faces faces, as a flat
      * index list (no copy of each triangle's index vector). */
    std::vector<unsigned int>
    largeComponents (const ScanMesh& mesh, std::size_t min_faces)
    {
      detail::UnionFind pieces (mesh.cloud->size ());
      for (const auto& poly : mesh.polygons)
        for (std::size_t k = 1; k < 3; ++k)
          pieces.unite (static_cast<std::size_t> (poly.vertices[k]), static_cast<std::size_t> (poly.vertices[0]));
      std::vector<std::size_t> faces_in (mesh.cloud->size (), 0);
      for (const auto& poly : mesh.polygons)
        ++faces_in[pieces.find (static_cast<std::size_t> (poly.vertices[0]))];
      std::vector<unsigned int> indices;
      indices.reserve (3 * mesh.polygons.size ());
      for (const auto& poly : mesh.polygons)
        if (faces_in[pieces.find (static_cast<std::size_t> (poly.vertices[0]))] >= min_faces)
          for (const auto v : poly.vertices)
            indices.push_back (static_cast<unsigned int> (v));
      return indices;
    }

    /** Garland-Heckbert collapses of the triangles \a indices of \a vertices down to \a target_faces. */
    void
    reduceWithMeshoptimizer (std::vector<unsigned int> indices, const pcl::PointCloud<pcl::PointNormal>& vertices,
                             std::size_t target_faces, ScanMesh& out)
    {
      // One call can stop short of the target when its ranking of collapses runs dry (it does on real
      // scans; doc/design.md#garland-heckbert-reduction-by-meshoptimizer); calling again on its own
      // output reclassifies the vertices and goes on. The error bound is relative to the mesh extent; 1 means "stop only at the target".
      const std::size_t target_indices = 3 * target_faces;
      for (int pass = 0; pass < 8 && indices.size () > target_indices; ++pass)
      {
        std::vector<unsigned int> simplified (indices.size ());
        const std::size_t count = meshopt_simplify (simplified.data (), indices.data (), indices.size (),
                                                    &vertices[0].x, vertices.size (), sizeof (pcl::PointNormal),
                                                    target_indices, 1.0f, 0, nullptr);
        const bool stalled = (count == indices.size ());
        simplified.resize (count);
        indices.swap (simplified);
        if (stalled)
          break;
      }
      compactMesh (indices, vertices, out);
    }

  }

  void
  QuadricMeshReduction::setTargetFaces (int faces)
  {
    if (faces < 4)
      PCL_TENSOR_THROW (BadArgumentException, "target face count must be at least 4, got " << faces);
    target_faces_ = faces;
  }

  void
  QuadricMeshReduction::setMinComponentFraction (double fraction)
  {
    if (!(fraction >= 0.0 && fraction < 1.0))
      PCL_TENSOR_THROW (BadArgumentException, "minimum component fraction must be in [0, 1), got " << fraction);
    min_component_fraction_ = fraction;
  }

  void
  QuadricMeshReduction::reduce (const ScanMesh& input, ScanMesh& reduced) const
  {
    if (input.polygons.empty ())
      PCL_TENSOR_THROW (InvalidScanException, "cannot reduce a mesh without faces");
    std::vector<unsigned int> indices =
        largeComponents (input, static_cast<std::size_t> (min_component_fraction_ * static_cast<double> (input.polygons.size ())));
    const std::size_t faces = indices.size () / 3;
    ScanMesh out;
    // At or under the target no edge collapses; the mesh is only cleaned, as every output is.
    reduceWithMeshoptimizer (std::move (indices), *input.cloud, static_cast<std::size_t> (target_faces_), out);
    if (out.polygons.empty ())
      PCL_TENSOR_THROW (InvalidScanException, "quadric simplification of " << faces << " faces left no face");
    out.viewpoint = input.viewpoint;
    reduced = std::move (out);
  }
}
