/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/surface/range_scan_triangulation.h>
#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>

#include "delaunay_2d.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace pcl
{
  namespace
  {
    using Triangle = std::array<pcl::index_t, 3>;

    /** Copy the finite points into the mesh cloud; returns, per input point, its vertex index or -1. */
    std::vector<pcl::index_t>
    copyFiniteVertices (const pcl::PointCloud<pcl::PointXYZ>& cloud, ScanMesh& mesh)
    {
      std::vector<pcl::index_t> vertex_of (cloud.size (), -1);
      mesh.cloud.reset (new pcl::PointCloud<pcl::PointNormal>);
      mesh.cloud->reserve (cloud.size ());
      for (std::size_t i = 0; i < cloud.size (); ++i)
      {
        if (!pcl::isXYZFinite (cloud[i]))
          continue;
        pcl::PointNormal p;
        p.getVector3fMap () = cloud[i].getVector3fMap ();
        p.getNormalVector3fMap ().setZero ();
        p.curvature = 0.0f;
        vertex_of[i] = static_cast<pcl::index_t> (mesh.cloud->size ());
        mesh.cloud->push_back (p);
      }
      mesh.cloud->is_dense = true;
      return vertex_of;
    }

    /** Two triangles per complete grid cell, split along the shorter diagonal; one for three corners.
      * Every triangle turns the same way around its cell, so that the mesh is consistently oriented. */
    std::vector<Triangle>
    triangulateGrid (const pcl::PointCloud<pcl::PointXYZ>& cloud, const std::vector<pcl::index_t>& vertex_of)
    {
      const std::size_t w = cloud.width, h = cloud.height;
      std::vector<Triangle> triangles;
      triangles.reserve (2 * w * h);
      auto dist2 = [&] (std::size_t a, std::size_t b) {
        return (cloud[a].getVector3fMap () - cloud[b].getVector3fMap ()).squaredNorm ();
      };
      for (std::size_t r = 0; r + 1 < h; ++r)
        for (std::size_t c = 0; c + 1 < w; ++c)
        {
          const std::size_t i00 = r * w + c, i01 = i00 + 1, i10 = i00 + w, i11 = i10 + 1;
          const pcl::index_t v00 = vertex_of[i00], v01 = vertex_of[i01], v10 = vertex_of[i10], v11 = vertex_of[i11];
          const int corners = (v00 >= 0) + (v01 >= 0) + (v10 >= 0) + (v11 >= 0);
          if (corners == 4)
          {
            if (dist2 (i00, i11) <= dist2 (i01, i10))
            {
              triangles.push_back ({v00, v10, v11});
              triangles.push_back ({v00, v11, v01});
            }
            else
            {
              triangles.push_back ({v00, v10, v01});
              triangles.push_back ({v01, v10, v11});
            }
          }
          else if (corners == 3)
          {
            Triangle t;
            int k = 0;
            for (const pcl::index_t v : {v00, v10, v11, v01})
              if (v >= 0)
                t[k++] = v;
            triangles.push_back (t);
          }
        }
      return triangles;
    }

    /** True when the points span no area (all on one line, or all equal): no triangle has area. */
    bool
    spanNoArea (const std::vector<Eigen::Vector2d>& uv)
    {
      Eigen::Vector2d mean = Eigen::Vector2d::Zero ();
      for (const auto& p : uv)
        mean += p;
      mean /= static_cast<double> (uv.size ());
      Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero ();
      for (const auto& p : uv)
        covariance += (p - mean) * (p - mean).transpose ();
      const Eigen::Vector2d spread = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> (covariance, Eigen::EigenvaluesOnly).eigenvalues ();
      return !(spread (0) > 1e-12 * spread (1));
    }

    /** The vertices projected onto the sensor's retinal plane. */
    std::vector<Eigen::Vector2d>
    projectToRetina (const ScanMesh& mesh, const ScanViewpoint& viewpoint)
    {
      std::vector<Eigen::Vector2d> uv (mesh.cloud->size ());
      for (std::size_t i = 0; i < mesh.cloud->size (); ++i)
        uv[i] = viewpoint.project ((*mesh.cloud)[i].getVector3fMap ().cast<double> ());
      return uv;
    }

    /** 2D Delaunay triangulation of the vertices at their retinal positions \a uv, counter-clockwise. */
    std::vector<Triangle>
    triangulateDelaunay (const std::vector<Eigen::Vector2d>& uv)
    {
      if (spanNoArea (uv))
        return {};
      std::vector<Triangle> triangles;
      for (const auto& t : detail::delaunayTriangulation (uv))
        triangles.push_back (Triangle{t[0], t[1], t[2]});
      return triangles;
    }

    template <typename Vector> double
    longestEdge (const Vector& a, const Vector& b, const Vector& c)
    {
      return std::max ({(b - a).norm (), (c - b).norm (), (a - c).norm ()});
    }

    double
    median (std::vector<double> values)
    {
      const auto middle = values.begin () + static_cast<std::ptrdiff_t> (values.size () / 2);
      std::nth_element (values.begin (), middle, values.end ());
      return *middle;
    }

    /** Per triangle, whether it belongs in the pruning statistics: false for those whose longest
      * retinal edge exceeds \a k median lengths. The sensor samples its retinal plane evenly, so
      * only a triangle across missing samples is that long there, even where the surface is steep. */
    std::vector<bool>
    spanNoGap (const std::vector<Triangle>& triangles, const std::vector<Eigen::Vector2d>& uv, double k)
    {
      if (triangles.empty ())
        return {};
      std::vector<double> longest (triangles.size ());
      for (std::size_t t = 0; t < triangles.size (); ++t)
        longest[t] = longestEdge (uv[triangles[t][0]], uv[triangles[t][1]], uv[triangles[t][2]]);
      const double limit = k * median (longest);
      std::vector<bool> in_statistics (triangles.size ());
      for (std::size_t t = 0; t < triangles.size (); ++t)
        in_statistics[t] = longest[t] <= limit;
      return in_statistics;
    }

    /** Drop triangles whose longest edge exceeds max(mean + k * stddev, floor * median) of the
      * longest edges of the triangles flagged in \a in_statistics (all when it is empty).
      * Section 2 states the rule over edge lengths; taken over every edge it would prune every
      * triangle of a regular grid, whose diagonals are all sqrt(2) times the mean. Over each
      * triangle's longest edge it keeps a regular grid whole, and on real scans it prunes the
      * bridges across depth jumps. The floor matters where the lengths barely vary (a tilted plane, a
      * synthetic render): there the stddev is rounding noise and mean + k * stddev would cut into a
      * smooth surface. See doc/design.md#edge-pruning. */
    std::vector<Triangle>
    pruneLongEdges (const ScanMesh& mesh, const std::vector<Triangle>& triangles, const std::vector<bool>& in_statistics,
                    double k, double floor_medians)
    {
      const auto vertex = [&] (pcl::index_t i) { return (*mesh.cloud)[i].getVector3fMap ().cast<double> ().eval (); };
      std::vector<double> longest (triangles.size ()), counted;
      counted.reserve (triangles.size ());
      for (std::size_t t = 0; t < triangles.size (); ++t)
      {
        longest[t] = longestEdge (vertex (triangles[t][0]), vertex (triangles[t][1]), vertex (triangles[t][2]));
        if (in_statistics.empty () || in_statistics[t])
          counted.push_back (longest[t]);
      }
      double sum = 0.0, sum2 = 0.0;
      for (const double l : counted)
      {
        sum += l;
        sum2 += l * l;
      }
      const double n = static_cast<double> (counted.size ());
      const double mean = sum / n;
      const double stddev = std::sqrt (std::max (0.0, sum2 / n - mean * mean));
      // A relative epsilon keeps equal edges equal despite rounding in the statistics.
      const double threshold = std::max (mean + k * stddev, floor_medians * median (counted)) * (1.0 + 1e-9);
      std::vector<Triangle> kept;
      kept.reserve (triangles.size ());
      for (std::size_t t = 0; t < triangles.size (); ++t)
        if (longest[t] <= threshold)
          kept.push_back (triangles[t]);
      return kept;
    }

    /** Store the non-degenerate triangles, all flipped or none so that most of the area faces the sensor.
      * Both triangulations wind every triangle the same way on the retinal plane, so one decision
      * keeps the mesh consistently oriented. Turning each triangle toward the sensor on its own would
      * reverse those that face away (grazing or noisy surface): their edges would no longer pair up,
      * and the reduction, which reads such edges as borders, could not collapse them. */
    void
    storeOriented (const std::vector<Triangle>& triangles, ScanMesh& mesh)
    {
      const auto vertex = [&] (pcl::index_t i) { return (*mesh.cloud)[i].getVector3fMap ().cast<double> ().eval (); };
      double facing = 0.0;
      mesh.polygons.clear ();
      mesh.polygons.reserve (triangles.size ());
      for (const auto& t : triangles)
      {
        const Eigen::Vector3d a = vertex (t[0]), b = vertex (t[1]), c = vertex (t[2]);
        const Eigen::Vector3d n = (b - a).cross (c - a);
        if (n.squaredNorm () == 0.0)
          continue;
        facing += n.dot (mesh.viewpoint.towardSensor ((a + b + c) / 3.0));
        pcl::Vertices v;
        v.vertices = {t[0], t[1], t[2]};
        mesh.polygons.push_back (std::move (v));
      }
      if (facing < 0.0)
        for (auto& poly : mesh.polygons)
          std::swap (poly.vertices[1], poly.vertices[2]);
    }
  }

  void
  RangeScanTriangulation::setEdgeStdDevs (double k)
  {
    if (!std::isfinite (k))
      PCL_TENSOR_THROW (BadArgumentException, "edge pruning factor must be finite, got " << k);
    edge_std_devs_ = k;
  }

  void
  RangeScanTriangulation::setEdgeFloorMedians (double floor)
  {
    if (!(floor >= 0.0) || !std::isfinite (floor))
      PCL_TENSOR_THROW (BadArgumentException, "edge pruning floor must be a non-negative number, got " << floor);
    edge_floor_medians_ = floor;
  }

  void
  RangeScanTriangulation::setGapRetinalMedians (double k)
  {
    // Under 1 it would leave the median triangle, or every triangle, out of the statistics.
    if (!(k >= 1.0))
      PCL_TENSOR_THROW (BadArgumentException, "gap factor must be at least 1, got " << k);
    gap_retinal_medians_ = k;
  }

  void
  RangeScanTriangulation::triangulate (const pcl::PointCloud<pcl::PointXYZ>& cloud, ScanMesh& mesh) const
  {
    mesh.viewpoint = viewpoint_;
    const std::vector<pcl::index_t> vertex_of = copyFiniteVertices (cloud, mesh);
    if (mesh.cloud->size () < 3)
      PCL_TENSOR_THROW (InvalidScanException, "triangulation needs at least 3 finite points, got " << mesh.cloud->size ());

    std::vector<Triangle> triangles;
    std::vector<bool> in_statistics;
    if (cloud.isOrganized () && !force_delaunay_)
      triangles = triangulateGrid (cloud, vertex_of);
    else
    {
      const std::vector<Eigen::Vector2d> uv = projectToRetina (mesh, viewpoint_);
      triangles = triangulateDelaunay (uv);
      in_statistics = spanNoGap (triangles, uv, gap_retinal_medians_);
    }
    if (triangles.empty ())
      PCL_TENSOR_THROW (InvalidScanException, "no triangle can be formed: the " << mesh.cloud->size ()
                        << " points are collinear or isolated on the retinal plane");
    storeOriented (pruneLongEdges (mesh, triangles, in_statistics, edge_std_devs_, edge_floor_medians_), mesh);
    if (mesh.polygons.empty ())
      PCL_TENSOR_THROW (InvalidScanException, "every triangle is degenerate (the points are collinear)");
  }
}
