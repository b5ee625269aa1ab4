/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/surface/range_view_projection.h>
#include <pcl/common/tensor_exceptions.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace pcl
{
  namespace
  {
    /** Pixels per side of a depth-range tile. */
    constexpr int kTile = 8;

    /** Calls \a f with the sensor model as a compile-time constant: one dispatch, then code for that model. */
    template <typename F> decltype (auto)
    withModel (ScanViewpoint::Model model, F&& f)
    {
      using Model = ScanViewpoint::Model;
      switch (model)
      {
        case Model::orthographic:
          return f (std::integral_constant<Model, Model::orthographic> ());
        case Model::pushbroom:
          return f (std::integral_constant<Model, Model::pushbroom> ());
        case Model::perspective:
          break;
      }
      return f (std::integral_constant<Model, Model::perspective> ());
    }

    /** Retinal coordinates of a sensor-frame point: (x, y) orthographic, (x, depth_scale y / z) pushbroom,
      * (x / z, y / z) perspective; false behind a perspective or pushbroom sensor. */
    template <ScanViewpoint::Model M> inline bool
    retinalAs (const Eigen::Vector3f& s, float depth_scale, float& u, float& v)
    {
      if constexpr (M == ScanViewpoint::Model::orthographic)
      {
        u = s.x (), v = s.y ();
        return true;
      }
      else if constexpr (M == ScanViewpoint::Model::pushbroom)
      {
        u = s.x (), v = depth_scale * s.y () / s.z ();
        return s.z () > 0.0f;
      }
      else
      {
        u = s.x () / s.z (), v = s.y () / s.z ();
        return s.z () > 0.0f;
      }
    }

    /** Hop count from each vertex to the nearest vertex on a border edge (an edge of one triangle),
      * up to \a max_hops; vertices farther away, or that no border reaches, get the largest int. */
    std::vector<int>
    borderHops (std::size_t vertex_count, const std::vector<pcl::Vertices>& polygons, int max_hops)
    {
      // Each edge is listed under its lower vertex; sorting those short lists finds the edges used
      // once (a hash map of edges cost more than the rest of the z-buffer).
      std::vector<std::uint32_t> start (vertex_count + 1, 0);
      for (const auto& poly : polygons)
        for (int k = 0; k < 3; ++k)
          ++start[std::min (poly.vertices[k], poly.vertices[(k + 1) % 3]) + 1];
      for (std::size_t v = 0; v < vertex_count; ++v)
        start[v + 1] += start[v];
      std::vector<std::uint32_t> upper (start.back ());
      {
        std::vector<std::uint32_t> fill (start.begin (), start.end () - 1);
        for (const auto& poly : polygons)
          for (int k = 0; k < 3; ++k)
          {
            const std::uint32_t a = poly.vertices[k], b = poly.vertices[(k + 1) % 3];
            upper[fill[std::min (a, b)]++] = std::max (a, b);
          }
      }
      // The distinct edges, and which of them lie on the border.
      std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
      edges.reserve (upper.size () / 2 + 1);
      std::vector<int> hops (vertex_count, std::numeric_limits<int>::max ());
      std::vector<std::uint32_t> queue;
      std::vector<std::uint32_t> degree (vertex_count + 1, 0);
      for (std::uint32_t a = 0; a < vertex_count; ++a)
      {
        std::sort (upper.begin () + start[a], upper.begin () + start[a + 1]);
        for (std::uint32_t i = start[a]; i < start[a + 1];)
        {
          std::uint32_t j = i + 1;
          while (j < start[a + 1] && upper[j] == upper[i])
            ++j;
          const std::uint32_t b = upper[i];
          edges.emplace_back (a, b);
          ++degree[a + 1];
          ++degree[b + 1];
          if (j - i == 1)
            for (const std::uint32_t v : {a, b})
              if (hops[v] != 0)
              {
                hops[v] = 0;
                queue.push_back (v);
              }
          i = j;
        }
      }
      for (std::size_t v = 0; v < vertex_count; ++v)
        degree[v + 1] += degree[v];
      std::vector<std::uint32_t> neighbours (degree.back ());
      {
        std::vector<std::uint32_t> fill (degree.begin (), degree.end () - 1);
        for (const auto& e : edges)
        {
          neighbours[fill[e.first]++] = e.second;
          neighbours[fill[e.second]++] = e.first;
        }
      }
      // Breadth first from every border vertex at once.
      for (std::size_t head = 0; head < queue.size (); ++head)
      {
        const std::uint32_t v = queue[head];
        if (hops[v] >= max_hops)
          break;  // the queue is in hop order: every later vertex is as far
        for (std::uint32_t k = degree[v]; k < degree[v + 1]; ++k)
        {
          const std::uint32_t n = neighbours[k];
          if (hops[n] > hops[v] + 1)
          {
            hops[n] = hops[v] + 1;
            queue.push_back (n);
          }
        }
      }
      return hops;
    }

    /** Curless & Levoy's per-vertex weight: cosine between the vertex normal and its line of sight,
      * times a ramp from 0 on the border to 1 at \a ramp_edges hops inside. Face normals are turned
      * toward the sensor before averaging, so the triangles' winding does not matter. */
    template <typename TowardSensor> std::vector<float>
    vertexWeights (const std::vector<Eigen::Vector3f>& s, const std::vector<pcl::Vertices>& polygons,
                   const TowardSensor& toward_sensor, double ramp_edges)
    {
      std::vector<Eigen::Vector3f> normals (s.size (), Eigen::Vector3f::Zero ());
      for (const auto& poly : polygons)
      {
        const Eigen::Vector3f& a = s[poly.vertices[0]];
        Eigen::Vector3f n = (s[poly.vertices[1]] - a).cross (s[poly.vertices[2]] - a);  // |n| = 2 area
        if (n.dot (toward_sensor (a)) < 0.0f)
          n = -n;
        for (int k = 0; k < 3; ++k)
          normals[poly.vertices[k]] += n;
      }
      // Beyond ramp_edges hops the ramp is 1 whatever the count.
      const std::vector<int> hops = borderHops (s.size (), polygons, static_cast<int> (std::ceil (std::min (ramp_edges, 1e6))));
      std::vector<float> weights (s.size (), 0.0f);
      for (std::size_t i = 0; i < s.size (); ++i)
      {
        const float n = normals[i].norm ();
        if (!(n > 0.0f))
          continue;
        const Eigen::Vector3f toward = toward_sensor (s[i]).normalized ();
        const double ramp = std::min (1.0, static_cast<double> (hops[i]) / ramp_edges);
        weights[i] = static_cast<float> (std::max (0.0f, normals[i].dot (toward) / n) * ramp);
      }
      return weights;
    }
  }

  RangeViewProjection::RangeViewProjection (const ScanMesh& mesh, double border_ramp_edges,
                                            double pixels_per_resolution, std::size_t max_pixels, double resolution)
  {
    if (!(border_ramp_edges > 0.0) || !(pixels_per_resolution > 0.0) || max_pixels == 0)
      PCL_TENSOR_THROW (pcl::BadArgumentException, "border ramp (" << border_ramp_edges << " edges), pixel density ("
                        << pixels_per_resolution << " per d_res) and pixel limit must be positive");
    model_ = mesh.viewpoint.model;
    scan_to_sensor_ = mesh.viewpoint.sensor_pose.inverse ().cast<float> ();

    std::vector<Eigen::Vector3f> s (mesh.cloud->size ());
    for (std::size_t i = 0; i < s.size (); ++i)
      s[i] = scan_to_sensor_ * (*mesh.cloud)[i].getVector3fMap ();

    // Depths of the vertices that triangles use (each once), in front of a perspective or pushbroom sensor.
    std::vector<char> used (s.size (), 0);
    for (const auto& poly : mesh.polygons)
      for (const auto idx : poly.vertices)
        used[idx] = 1;
    std::vector<float> depths;
    depths.reserve (s.size ());
    for (std::size_t i = 0; i < s.size (); ++i)
      if (used[i] && (model_ == ScanViewpoint::Model::orthographic || s[i].z () > 0.0f))
        depths.push_back (s[i].z ());
    if (depths.empty ())
      PCL_TENSOR_THROW (InvalidScanException, "range view has no triangle in front of its sensor");
    std::nth_element (depths.begin (), depths.begin () + depths.size () / 2, depths.end ());
    const float median_depth = depths[depths.size () / 2];
    // A pushbroom's y/z is scaled to a length at the median depth, so that square pixels suit it.
    depth_scale_ = model_ == ScanViewpoint::Model::pushbroom ? median_depth : 1.0f;

    // Retinal coordinates once per vertex (each is shared by about six triangles); the image covers
    // those of the vertices a triangle uses.
    std::vector<Retinal> uv (s.size ());
    withModel (model_, [&] (auto model) {
      for (std::size_t i = 0; i < s.size (); ++i)
        uv[i].in_front = retinalAs<decltype (model)::value> (s[i], depth_scale_, uv[i].u, uv[i].v);
    });
    float umin = std::numeric_limits<float>::max (), vmin = umin, umax = -umin, vmax = -umin;
    for (std::size_t i = 0; i < s.size (); ++i)
      if (used[i] && uv[i].in_front)
      {
        umin = std::min (umin, uv[i].u), umax = std::max (umax, uv[i].u);
        vmin = std::min (vmin, uv[i].v), vmax = std::max (vmax, uv[i].v);
      }
    if (!(umax >= umin) || !(vmax >= vmin))
      PCL_TENSOR_THROW (InvalidScanException, "range view has no triangle in front of its sensor");

    // d_res on the retinal plane: a length, except for a perspective sensor's d_res / median depth.
    if (!(resolution > 0.0))
      resolution = meshResolution (mesh);
    double pixel = resolution / pixels_per_resolution / (model_ == ScanViewpoint::Model::perspective ? median_depth : 1.0);
    if (!(pixel > 0.0))
      PCL_TENSOR_THROW (InvalidScanException, "range view has no extent (d_res " << resolution << ")");
    const double cells = ((umax - umin) / pixel + 2.0) * ((vmax - vmin) / pixel + 2.0);
    if (cells > static_cast<double> (max_pixels))
      pixel *= std::sqrt (cells / static_cast<double> (max_pixels));
    u0_ = umin - static_cast<float> (pixel) * 0.5f;
    v0_ = vmin - static_cast<float> (pixel) * 0.5f;
    inv_pixel_ = static_cast<float> (1.0 / pixel);
    width_ = static_cast<int> ((umax - u0_) * inv_pixel_) + 2;
    height_ = static_cast<int> ((vmax - v0_) * inv_pixel_) + 2;

    // Back along the line of sight: the sensor frame's -z, the point itself, or its part across the sweep.
    const auto toward_sensor = [this] (const Eigen::Vector3f& p) -> Eigen::Vector3f {
      switch (model_)
      {
        case ScanViewpoint::Model::orthographic:
          return -Eigen::Vector3f::UnitZ ();
        case ScanViewpoint::Model::pushbroom:
          return Eigen::Vector3f (0.0f, -p.y (), -p.z ());
        case ScanViewpoint::Model::perspective:
          break;
      }
      return -p;
    };
    rayCoefficients (ray_origin_, ray_direction_);
    const std::vector<float> weights = vertexWeights (s, mesh.polygons, toward_sensor, border_ramp_edges);
    withModel (model_, [&] (auto model) { rasterizeAs<decltype (model)::value> (s, uv, weights, mesh.polygons); });
    buildTiles ();
  }

  template <ScanViewpoint::Model M> void
  RangeViewProjection::rasterizeAs (const std::vector<Eigen::Vector3f>& s, const std::vector<Retinal>& uv,
                                    const std::vector<float>& weights, const std::vector<pcl::Vertices>& polygons)
  {
    triangle_.assign (static_cast<std::size_t> (width_) * height_, -1);
    std::vector<float> zbuf (triangle_.size (), std::numeric_limits<float>::max ());
    planes_.clear ();
    planes_.reserve (polygons.size ());
    const double pixel = 1.0 / inv_pixel_;
    for (const auto& poly : polygons)
    {
      const Retinal& p0 = uv[poly.vertices[0]];
      const Retinal& p1 = uv[poly.vertices[1]];
      const Retinal& p2 = uv[poly.vertices[2]];
      if (!p0.in_front || !p1.in_front || !p2.in_front)
        continue;
      const double u[3] = {p0.u, p1.u, p2.u}, v[3] = {p0.v, p1.v, p2.v};
      const double eu1 = u[1] - u[0], ev1 = v[1] - v[0], eu2 = u[2] - u[0], ev2 = v[2] - v[0];
      const double det = eu1 * ev2 - eu2 * ev1;
      // Edge-on triangles cover no pixel centre reliably and their plane is ill-defined.
      if (!(std::abs (det) > 1e-6 * pixel * pixel))
        continue;
      const double inv_det = 1.0 / det;

      const double lo_u = std::min ({u[0], u[1], u[2]}), hi_u = std::max ({u[0], u[1], u[2]});
      const double lo_v = std::min ({v[0], v[1], v[2]}), hi_v = std::max ({v[0], v[1], v[2]});
      // The pixel centres in the bounding box, widened by more than the inside test's slack: at a pixel
      // per d_res most triangles hold none, and they are done with here.
      const double widen = 1e-3 * std::max (hi_u - lo_u, hi_v - lo_v);
      const int c0 = std::max (0, static_cast<int> (std::ceil ((lo_u - widen - u0_) * inv_pixel_ - 0.5)));
      const int c1 = std::min (width_ - 1, static_cast<int> (std::floor ((hi_u + widen - u0_) * inv_pixel_ - 0.5)));
      const int r0 = std::max (0, static_cast<int> (std::ceil ((lo_v - widen - v0_) * inv_pixel_ - 0.5)));
      const int r1 = std::min (height_ - 1, static_cast<int> (std::floor ((hi_v + widen - v0_) * inv_pixel_ - 0.5)));
      if (c0 > c1 || r0 > r1)
        continue;

      Plane plane;
      plane.u = static_cast<float> (u[0]);
      plane.v = static_cast<float> (v[0]);
      setDepthTerms (s[poly.vertices[0]], s[poly.vertices[1]], s[poly.vertices[2]], plane);
      // The weight is affine in (u, v), relative to corner 0 for float precision.
      const double w0 = weights[poly.vertices[0]], w1 = weights[poly.vertices[1]] - w0, w2 = weights[poly.vertices[2]] - w0;
      plane.w0 = static_cast<float> (w0);
      plane.wu = static_cast<float> ((w1 * ev2 - w2 * ev1) * inv_det);
      plane.wv = static_cast<float> ((eu1 * w2 - eu2 * w1) * inv_det);
      const std::int32_t id = static_cast<std::int32_t> (planes_.size ());
      bool covers = false;
      // Barycentric inside test with a little slack so that shared edges leave no crack.
      const double eps = -1e-4;
      for (int r = r0; r <= r1; ++r)
      {
        const double pv = v0_ + (r + 0.5) * pixel - v[0];
        const float dv = static_cast<float> (v0_ + (r + 0.5) * pixel) - plane.v;
        for (int c = c0; c <= c1; ++c)
        {
          const double pu = u0_ + (c + 0.5) * pixel - u[0];
          const double b1 = (pu * ev2 - eu2 * pv) * inv_det, b2 = (eu1 * pv - pu * ev1) * inv_det;
          if (b1 < eps || b2 < eps || 1.0 - b1 - b2 < eps)
            continue;
          const float z = depthAs<M> (plane, static_cast<float> (u0_ + (c + 0.5) * pixel) - plane.u, dv);
          const std::size_t cell = static_cast<std::size_t> (r) * width_ + c;
          if (z < zbuf[cell])
          {
            zbuf[cell] = z;
            triangle_[cell] = id;
            covers = true;
          }
        }
      }
      // A triangle that no pixel keeps is never looked up: its plane is not stored.
      if (covers)
        planes_.push_back (plane);
    }
  }

  void
  RangeViewProjection::buildTiles ()
  {
    tiles_x_ = (width_ + kTile - 1) / kTile;
    tiles_y_ = (height_ + kTile - 1) / kTile;
    tile_min_.assign (static_cast<std::size_t> (tiles_x_) * tiles_y_, std::numeric_limits<float>::max ());
    tile_max_.assign (tile_min_.size (), -std::numeric_limits<float>::max ());
    const float pixel = 1.0f / inv_pixel_;
    for (int r = 0; r < height_; ++r)
      for (int c = 0; c < width_; ++c)
      {
        const std::int32_t id = triangle_[static_cast<std::size_t> (r) * width_ + c];
        if (id < 0)
          continue;
        // The depth range covers the whole pixel, since queries are answered off the pixel centre.
        const Plane& plane = planes_[id];
        const std::size_t tile = static_cast<std::size_t> (r / kTile) * tiles_x_ + c / kTile;
        for (const float du : {0.0f, 1.0f})
          for (const float dv : {0.0f, 1.0f})
          {
            const float z = surfaceDepth (plane, u0_ + (c + du) * pixel, v0_ + (r + dv) * pixel);
            tile_min_[tile] = std::min (tile_min_[tile], z);
            tile_max_[tile] = std::max (tile_max_[tile], z);
          }
      }
  }

  bool
  RangeViewProjection::pixelOf (float u, float v, int& col, int& row) const
  {
    const float fc = (u - u0_) * inv_pixel_, fr = (v - v0_) * inv_pixel_;
    if (!(fc >= 0.0f && fr >= 0.0f && fc < static_cast<float> (width_) && fr < static_cast<float> (height_)))
      return false;
    col = static_cast<int> (fc);
    row = static_cast<int> (fr);
    return true;
  }

  bool
  RangeViewProjection::retinal (const Eigen::Vector3f& s, float& u, float& v) const
  {
    return withModel (model_, [&] (auto model) { return retinalAs<decltype (model)::value> (s, depth_scale_, u, v); });
  }

  void
  RangeViewProjection::rayCoefficients (Eigen::Matrix3d& origin, Eigen::Matrix3d& direction) const
  {
    // Columns: the constant term and the slopes in u and v.
    origin.setZero ();
    direction.setZero ();
    direction (2, 0) = 1.0;
    switch (model_)
    {
      case ScanViewpoint::Model::orthographic:
        origin (0, 1) = origin (1, 2) = 1.0;
        return;
      case ScanViewpoint::Model::pushbroom:
        origin (0, 1) = 1.0;
        direction (1, 2) = 1.0 / depth_scale_;
        return;
      case ScanViewpoint::Model::perspective:
        break;
    }
    direction (0, 1) = direction (1, 2) = 1.0;
  }

  void
  RangeViewProjection::setDepthTerms (const Eigen::Vector3f& a, const Eigen::Vector3f& b, const Eigen::Vector3f& c,
                                      Plane& plane) const
  {
    // The line of sight o + t r meets the plane n.(x - a) = 0 at t = n.(a - o) / n.r, and r.z = 1 makes
    // t the depth. o and r are affine in (u, v), so t is a ratio of two affine functions of (u, v);
    // both are written about the first corner's (u, v) for float precision.
    const Eigen::Vector3d corner = a.cast<double> ();
    const Eigen::Vector3d n = (b - a).cast<double> ().cross ((c - a).cast<double> ()).normalized ();
    const Eigen::Matrix3d& origin = ray_origin_;
    const Eigen::Matrix3d& direction = ray_direction_;
    const Eigen::Vector3d at (1.0, plane.u, plane.v);
    const double a0 = n.dot (corner - origin * at), au = -n.dot (origin.col (1)), av = -n.dot (origin.col (2));
    const double b0 = n.dot (direction * at), bu = n.dot (direction.col (1)), bv = n.dot (direction.col (2));
    // Each model keeps only the terms that vary: an orthographic depth is affine (b = 1), a perspective
    // one's inverse is (a constant), and a pushbroom's numerator varies in u only, its denominator in v.
    switch (model_)
    {
      case ScanViewpoint::Model::orthographic:
        plane.d0 = static_cast<float> (a0 / b0), plane.du = static_cast<float> (au / b0), plane.dv = static_cast<float> (av / b0);
        return;
      case ScanViewpoint::Model::pushbroom:
        plane.d0 = static_cast<float> (a0), plane.du = static_cast<float> (au);
        plane.e0 = static_cast<float> (b0), plane.dv = static_cast<float> (bv);
        return;
      case ScanViewpoint::Model::perspective:
        break;
    }
    plane.d0 = static_cast<float> (b0 / a0), plane.du = static_cast<float> (bu / a0), plane.dv = static_cast<float> (bv / a0);
  }

  float
  RangeViewProjection::surfaceDepth (const Plane& plane, float u, float v) const
  {
    return withModel (model_, [&] (auto model) { return depthAs<decltype (model)::value> (plane, u - plane.u, v - plane.v); });
  }

  template <ScanViewpoint::Model M> float
  RangeViewProjection::depthAs (const Plane& plane, float du, float dv)
  {
    if constexpr (M == ScanViewpoint::Model::orthographic)
      return plane.d0 + plane.du * du + plane.dv * dv;
    else if constexpr (M == ScanViewpoint::Model::pushbroom)
      return (plane.d0 + plane.du * du) / (plane.e0 + plane.dv * dv);
    else
      return 1.0f / (plane.d0 + plane.du * du + plane.dv * dv);
  }

  namespace
  {
    /** Along each line of \a length cells (stride \a step between cells, \a lines lines \a line_step
      * apart), mark the cells within \a margin of a marked cell of \a in. */
    void
    dilateLines (const std::vector<std::uint8_t>& in, std::vector<std::uint8_t>& out, int lines, int length,
                 std::size_t line_step, std::size_t step, int margin)
    {
      for (int l = 0; l < lines; ++l)
      {
        const std::size_t base = static_cast<std::size_t> (l) * line_step;
        int last = -margin - 1;  // the last marked cell seen, going forward
        for (int k = 0; k < length; ++k)
        {
          if (in[base + k * step])
            last = k;
          out[base + k * step] = k - last <= margin;
        }
        last = length + margin;  // going backward
        for (int k = length - 1; k >= 0; --k)
        {
          if (in[base + k * step])
            last = k;
          out[base + k * step] |= last - k <= margin;
        }
      }
    }
  }

  void
  RangeViewProjection::markEmptySpace (int margin_pixels)
  {
    if (margin_pixels < 0)
      PCL_TENSOR_THROW (BadArgumentException, "empty-space margin must be non-negative, got " << margin_pixels);
    const std::size_t n = triangle_.size ();
    std::vector<std::uint8_t> covered (n), rows (n);
    for (std::size_t i = 0; i < n; ++i)
      covered[i] = triangle_[i] >= 0;
    // A square neighbourhood is a dilation along the rows, then along the columns.
    dilateLines (covered, rows, height_, width_, static_cast<std::size_t> (width_), 1, margin_pixels);
    dilateLines (rows, covered, width_, height_, 1, static_cast<std::size_t> (width_), margin_pixels);
    // Only the background around the view counts: a hole the surface encloses may be a dropout (a
    // dark or shiny patch, a triangulation scanner's shadow) rather than space seen through.
    empty_.assign (n, 0);
    std::vector<std::size_t> stack;
    const auto push = [&] (int c, int r) {
      const std::size_t i = static_cast<std::size_t> (r) * width_ + c;
      if (!covered[i] && !empty_[i])
      {
        empty_[i] = 1;
        stack.push_back (i);
      }
    };
    for (int c = 0; c < width_; ++c)
      push (c, 0), push (c, height_ - 1);
    for (int r = 0; r < height_; ++r)
      push (0, r), push (width_ - 1, r);
    while (!stack.empty ())
    {
      const std::size_t i = stack.back ();
      stack.pop_back ();
      const int c = static_cast<int> (i % width_), r = static_cast<int> (i / width_);
      if (c > 0) push (c - 1, r);
      if (c + 1 < width_) push (c + 1, r);
      if (r > 0) push (c, r - 1);
      if (r + 1 < height_) push (c, r + 1);
    }
  }

  bool
  RangeViewProjection::seenEmpty (const Eigen::Vector3f& p) const
  {
    if (empty_.empty ())
      return false;
    float u, v;
    int col, row;
    return retinal (scan_to_sensor_ * p, u, v) && pixelOf (u, v, col, row) && empty_[static_cast<std::size_t> (row) * width_ + col];
  }

  bool
  RangeViewProjection::sample (const Eigen::Vector3f& p, Sample& sample) const
  {
    return sampleSensor (scan_to_sensor_ * p, sample);
  }

  bool
  RangeViewProjection::sampleSensor (const Eigen::Vector3f& s, Sample& out) const
  {
    // One dispatch per sample: integration samples millions of voxels per view.
    return withModel (model_, [&] (auto model) { return sampleAs<decltype (model)::value> (s, out); });
  }

  template <ScanViewpoint::Model M> bool
  RangeViewProjection::sampleAs (const Eigen::Vector3f& s, Sample& out) const
  {
    float u, v;
    int col, row;
    if (!retinalAs<M> (s, depth_scale_, u, v) || !pixelOf (u, v, col, row))
      return false;
    const std::int32_t id = triangle_[static_cast<std::size_t> (row) * width_ + col];
    if (id < 0)
      return false;
    const Plane& plane = planes_[id];
    const float du = u - plane.u, dv = v - plane.v;
    // Moving the depth by dz moves along the line of sight by dz |r| (r.z = 1): the range from the
    // line's origin over the depth.
    const float z = depthAs<M> (plane, du, dv);
    if constexpr (M == ScanViewpoint::Model::orthographic)
      out.distance = z - s.z ();
    else
    {
      if (!(z > 0.0f) || !std::isfinite (z))
        return false;
      const float range = M == ScanViewpoint::Model::perspective ? s.norm () : s.tail<2> ().norm ();
      out.distance = (z - s.z ()) * range / s.z ();
    }
    out.weight = std::min (1.0f, std::max (0.0f, plane.w0 + plane.wu * du + plane.wv * dv));
    return true;
  }

  bool
  RangeViewProjection::depthRange (const Eigen::Vector3f& lo, const Eigen::Vector3f& hi, float& min_depth,
                                   float& max_depth) const
  {
    int c0 = 0, c1 = tiles_x_ - 1, r0 = 0, r1 = tiles_y_ - 1;
    // A box reaching behind a perspective or pushbroom sensor projects unboundedly: answer for the whole image.
    if (model_ == ScanViewpoint::Model::orthographic || lo.z () > 0.0f)
    {
      // u and v are monotonic in each coordinate over such a box, so its corners bound its projection.
      float umin = std::numeric_limits<float>::max (), vmin = umin, umax = -umin, vmax = -umin;
      for (int k = 0; k < 8; ++k)
      {
        const Eigen::Vector3f p ((k & 1) ? hi.x () : lo.x (), (k & 2) ? hi.y () : lo.y (), (k & 4) ? hi.z () : lo.z ());
        float u, v;
        retinal (p, u, v);
        umin = std::min (umin, u), umax = std::max (umax, u);
        vmin = std::min (vmin, v), vmax = std::max (vmax, v);
      }
      const float fc0 = (umin - u0_) * inv_pixel_, fc1 = (umax - u0_) * inv_pixel_;
      const float fr0 = (vmin - v0_) * inv_pixel_, fr1 = (vmax - v0_) * inv_pixel_;
      if (fc1 < 0.0f || fr1 < 0.0f || fc0 >= static_cast<float> (width_) || fr0 >= static_cast<float> (height_))
        return false;
      c0 = std::max (0, static_cast<int> (fc0)) / kTile;
      c1 = std::min (width_ - 1, static_cast<int> (fc1)) / kTile;
      r0 = std::max (0, static_cast<int> (fr0)) / kTile;
      r1 = std::min (height_ - 1, static_cast<int> (fr1)) / kTile;
    }
    min_depth = std::numeric_limits<float>::max ();
    max_depth = -std::numeric_limits<float>::max ();
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c)
      {
        const std::size_t tile = static_cast<std::size_t> (r) * tiles_x_ + c;
        min_depth = std::min (min_depth, tile_min_[tile]);
        max_depth = std::max (max_depth, tile_max_[tile]);
      }
    return min_depth <= max_depth;
  }

  std::size_t
  RangeViewProjection::memoryBytes () const
  {
    return triangle_.size () * sizeof (std::int32_t) + planes_.size () * sizeof (Plane)
         + (tile_min_.size () + tile_max_.size ()) * sizeof (float) + empty_.size ();
  }
}
