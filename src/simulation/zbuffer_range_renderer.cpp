/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/simulation/zbuffer_range_renderer.h>
#include <pcl/common/tensor_exceptions.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl
{
  namespace
  {
    /** Barycentric slack: pixels exactly on an edge shared by two triangles must not fall through both
      * because of rounding. A point accepted by it lies within ~1e-12 edge lengths of the triangle. */
    constexpr double kEdgeSlack = 1e-12;

    double
    focalLength (const RangeCameraParams& p)
    {
      return 0.5 * p.width / std::tan (0.5 * p.fov_deg * M_PI / 180.0);
    }
  }

  bool
  intersectRayTriangle (const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                        const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                        double& t)
  {
    const Eigen::Vector3d e1 = b - a, e2 = c - a;
    const Eigen::Vector3d p = direction.cross (e2);
    const double det = e1.dot (p);
    // A ray parallel to the triangle's plane sees at most its edge, which has no area to render.
    if (det == 0.0 || !std::isfinite (det))
      return false;
    const double inv = 1.0 / det;
    const Eigen::Vector3d s = origin - a;
    const double u = s.dot (p) * inv;
    if (u < -kEdgeSlack || u > 1.0 + kEdgeSlack)
      return false;
    const Eigen::Vector3d q = s.cross (e1);
    const double v = direction.dot (q) * inv;
    if (v < -kEdgeSlack || u + v > 1.0 + kEdgeSlack)
      return false;
    t = e2.dot (q) * inv;
    return t > 0.0;
  }

  void
  ZBufferRangeRenderer::setMesh (const ScanMesh& mesh)
  {
    if (mesh.polygons.empty ())
      PCL_TENSOR_THROW (InvalidScanException, "ZBufferRangeRenderer: the mesh has no triangles");
    const auto& pts = *mesh.cloud;
    std::vector<Triangle> triangles;
    triangles.reserve (mesh.polygons.size ());
    for (const auto& poly : mesh.polygons)
    {
      if (poly.vertices.size () != 3)
        PCL_TENSOR_THROW (InvalidScanException, "ZBufferRangeRenderer: a polygon has "
                          << poly.vertices.size () << " vertices; only triangles are rendered");
      Eigen::Vector3d v[3];
      for (int k = 0; k < 3; ++k)
      {
        if (poly.vertices[k] < 0 || static_cast<std::size_t> (poly.vertices[k]) >= pts.size ())
          PCL_TENSOR_THROW (InvalidScanException, "ZBufferRangeRenderer: vertex index "
                            << poly.vertices[k] << " out of range (" << pts.size () << " vertices)");
        v[k] = pts[poly.vertices[k]].getVector3fMap ().cast<double> ();
        // A NaN corner would turn the triangle's pixel bounds into undefined integer casts.
        if (!v[k].allFinite ())
          PCL_TENSOR_THROW (InvalidScanException, "ZBufferRangeRenderer: vertex " << poly.vertices[k]
                            << " of a triangle is not finite");
      }
      triangles.push_back ({v[0], v[1], v[2]});
    }
    triangles_.swap (triangles);
  }

  void
  ZBufferRangeRenderer::setCameraParams (const RangeCameraParams& params)
  {
    if (params.width <= 0 || params.height <= 0)
      PCL_TENSOR_THROW (pcl::BadArgumentException, "range camera size must be positive, got "
                        << params.width << "x" << params.height);
    if (!params.orthographic && !(params.fov_deg > 0.0 && params.fov_deg < 180.0))
      PCL_TENSOR_THROW (pcl::BadArgumentException, "range camera field of view must be in (0, 180) degrees, got "
                        << params.fov_deg);
    if ((params.orthographic || params.pushbroom) && !(params.ortho_extent > 0.0 && std::isfinite (params.ortho_extent)))
      PCL_TENSOR_THROW (pcl::BadArgumentException, "orthographic extent must be positive, got "
                        << params.ortho_extent);
    if (params.orthographic && params.pushbroom)
      PCL_TENSOR_THROW (pcl::BadArgumentException, "a range camera is orthographic or pushbroom, not both");
    params_ = params;
  }

  PixelRay
  ZBufferRangeRenderer::pixelRay (int col, int row) const
  {
    const double x = col + 0.5 - 0.5 * params_.width;
    const double y = 0.5 * params_.height - (row + 0.5);
    PixelRay ray;
    const double pixel = params_.ortho_extent / params_.width;
    if (params_.orthographic)
      ray.origin = Eigen::Vector3d (x * pixel, y * pixel, 0.0);
    else if (params_.pushbroom)
    {
      ray.origin = Eigen::Vector3d (x * pixel, 0.0, 0.0);
      ray.direction = Eigen::Vector3d (0.0, y / focalLength (params_), -1.0);
    }
    else
    {
      const double f = focalLength (params_);
      ray.direction = Eigen::Vector3d (x / f, y / f, -1.0);
    }
    return ray;
  }

  bool
  ZBufferRangeRenderer::pixelBounds (const Triangle& t, int& c0, int& c1, int& r0, int& r1) const
  {
    const Eigen::Vector3d* v[3] = {&t.a, &t.b, &t.c};
    const double max_z = std::max ({t.a.z (), t.b.z (), t.c.z ()});
    // Every ray starts at z = 0 and goes toward -z: a triangle wholly at z >= 0 is never hit.
    if (std::min ({t.a.z (), t.b.z (), t.c.z ()}) >= 0.0)
      return false;
    double cmin = std::numeric_limits<double>::max (), cmax = -cmin, rmin = cmin, rmax = -cmin;
    if (!params_.orthographic && max_z >= 0.0)
    {
      // The triangle straddles the sensor plane, where projection is undefined: test every pixel.
      cmin = rmin = 0.0;
      cmax = params_.width - 1.0;
      rmax = params_.height - 1.0;
    }
    else
    {
      // Columns: perspective, or parallel (orthographic, pushbroom); rows: parallel only when orthographic.
      const double f = focalLength (params_), per_metre = params_.width / params_.ortho_extent;
      for (const auto* p : v)
      {
        const double col = (params_.orthographic || params_.pushbroom) ? per_metre * p->x () : f * p->x () / -p->z ();
        const double row_offset = params_.orthographic ? per_metre * p->y () : f * p->y () / -p->z ();
        const double col_pixel = col + 0.5 * params_.width - 0.5;
        const double row = 0.5 * params_.height - 0.5 - row_offset;
        cmin = std::min (cmin, col_pixel); cmax = std::max (cmax, col_pixel);
        rmin = std::min (rmin, row); rmax = std::max (rmax, row);
      }
    }
    // One pixel of margin keeps the box conservative against rounding in the projection.
    c0 = static_cast<int> (std::max (0.0, std::floor (cmin) - 1.0));
    r0 = static_cast<int> (std::max (0.0, std::floor (rmin) - 1.0));
    c1 = static_cast<int> (std::min (params_.width - 1.0, std::ceil (cmax) + 1.0));
    r1 = static_cast<int> (std::min (params_.height - 1.0, std::ceil (rmax) + 1.0));
    return c0 <= c1 && r0 <= r1;
  }

  RenderedView
  ZBufferRangeRenderer::render (const Eigen::Affine3d& sensor_pose) const
  {
    if (triangles_.empty ())
      PCL_TENSOR_THROW (InvalidScanException, "ZBufferRangeRenderer::render: no mesh was set");
    const int w = params_.width, h = params_.height;
    std::vector<PixelRay> rays (static_cast<std::size_t> (w) * h);
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c)
        rays[static_cast<std::size_t> (r) * w + c] = pixelRay (c, r);

    std::vector<double> depth (rays.size (), std::numeric_limits<double>::infinity ());
    const Eigen::Affine3d to_sensor = sensor_pose.inverse ();
    for (const auto& tm : triangles_)
    {
      const Triangle ts{to_sensor * tm.a, to_sensor * tm.b, to_sensor * tm.c};
      int c0, c1, r0, r1;
      if (!pixelBounds (ts, c0, c1, r0, r1))
        continue;
      for (int r = r0; r <= r1; ++r)
        for (int c = c0; c <= c1; ++c)
        {
          const std::size_t i = static_cast<std::size_t> (r) * w + c;
          double t;
          if (intersectRayTriangle (rays[i].origin, rays[i].direction, ts.a, ts.b, ts.c, t) && t < depth[i])
            depth[i] = t;
        }
    }

    RenderedView view;
    view.pose = sensor_pose;
    view.viewpoint.sensor_pose = Eigen::AngleAxisd (M_PI, Eigen::Vector3d::UnitX ());
    view.viewpoint.model = params_.orthographic ? ScanViewpoint::Model::orthographic
                           : params_.pushbroom  ? ScanViewpoint::Model::pushbroom
                                                : ScanViewpoint::Model::perspective;
    auto& cloud = *view.cloud;
    cloud.resize (static_cast<std::size_t> (w) * h);
    cloud.width = static_cast<std::uint32_t> (w);
    cloud.height = static_cast<std::uint32_t> (h);
    bool dense = true;
    for (std::size_t i = 0; i < rays.size (); ++i)
    {
      if (std::isinf (depth[i]))
      {
        const float nan = std::numeric_limits<float>::quiet_NaN ();
        cloud[i].x = cloud[i].y = cloud[i].z = nan;
        dense = false;
        continue;
      }
      cloud[i].getVector3fMap () = (rays[i].origin + depth[i] * rays[i].direction).cast<float> ();
    }
    cloud.is_dense = dense;
    return view;
  }
}
