/*
 * pcl_tensor: automatic pairwise registration of range images with tensors
 * (Mian, Bennamoun & Owens, IJCV 2006).
 */
#include <pcl/features/tensor_grid.h>
#include <pcl/common/tensor_exceptions.h>
#include "../common/union_find.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace pcl
{
  void
  TensorSurfaceGrid::setMesh (const std::vector<Eigen::Vector3d>& vertices,
                              const std::vector<pcl::Vertices>& polygons)
  {
    if (polygons.empty ())
      PCL_TENSOR_THROW (InvalidScanException, "[pcl::TensorSurfaceGrid::setMesh] the mesh has no polygons");
    const int n = static_cast<int> (vertices.size ());
    std::vector<std::array<int, 3>> faces;
    faces.reserve (polygons.size ());
    for (std::size_t f = 0; f < polygons.size (); ++f)
    {
      const auto& v = polygons[f].vertices;
      if (v.size () != 3)
        PCL_TENSOR_THROW (InvalidScanException, "[pcl::TensorSurfaceGrid::setMesh] polygon " << f << " has "
                          << v.size () << " vertices; only triangles are supported");
      for (const auto idx : v)
        if (idx < 0 || idx >= n)
          PCL_TENSOR_THROW (InvalidScanException, "[pcl::TensorSurfaceGrid::setMesh] polygon " << f
                            << " refers to vertex " << idx << " of " << n);
      faces.push_back ({static_cast<int> (v[0]), static_cast<int> (v[1]), static_cast<int> (v[2])});
    }
    for (int i = 0; i < n; ++i)
      if (!vertices[i].allFinite ())
        PCL_TENSOR_THROW (InvalidScanException, "[pcl::TensorSurfaceGrid::setMesh] vertex " << i << " is not finite");

    vertices_ = vertices;
    faces_ = std::move (faces);
    const std::size_t nf = faces_.size ();
    face_normals_.assign (nf, Eigen::Vector3d::Zero ());
    face_centres_.assign (nf, Eigen::Vector3d::Zero ());
    face_radii_.assign (nf, 0.0);
    mesh_area_ = 0.0;
    std::vector<int> counts (n + 1, 0);
    for (std::size_t f = 0; f < nf; ++f)
    {
      const auto& t = faces_[f];
      const Eigen::Vector3d& a = vertices_[t[0]];
      const Eigen::Vector3d& b = vertices_[t[1]];
      const Eigen::Vector3d& c = vertices_[t[2]];
      const Eigen::Vector3d cross = (b - a).cross (c - a);
      const double norm = cross.norm ();
      mesh_area_ += 0.5 * norm;
      if (norm > 0.0)
        face_normals_[f] = cross / norm;
      const Eigen::Vector3d centre = (a + b + c) / 3.0;
      face_centres_[f] = centre;
      face_radii_[f] = std::max ({(a - centre).norm (), (b - centre).norm (), (c - centre).norm ()});
      for (const int v : t)
        ++counts[v + 1];
    }
    vertex_face_offsets_.assign (n + 1, 0);
    for (int i = 0; i < n; ++i)
      vertex_face_offsets_[i + 1] = vertex_face_offsets_[i] + counts[i + 1];
    vertex_faces_.assign (vertex_face_offsets_[n], -1);
    std::vector<int> fill (vertex_face_offsets_.begin (), vertex_face_offsets_.end () - 1);
    for (std::size_t f = 0; f < nf; ++f)
      for (const int v : faces_[f])
        vertex_faces_[fill[v]++] = static_cast<int> (f);

    // Connected components over shared vertices (union-find), and each one's longest edge.
    detail::UnionFind pieces (static_cast<std::size_t> (n));
    for (const auto& t : faces_)
    {
      pieces.unite (static_cast<std::size_t> (t[0]), static_cast<std::size_t> (t[1]));
      pieces.unite (static_cast<std::size_t> (t[1]), static_cast<std::size_t> (t[2]));
    }
    std::vector<int> component_of_root (n, -1);
    std::vector<int> vertex_component (n, -1);
    int components = 0;
    for (int i = 0; i < n; ++i)
      if (vertex_face_offsets_[i + 1] > vertex_face_offsets_[i])
      {
        const std::size_t r = pieces.find (static_cast<std::size_t> (i));
        if (component_of_root[r] < 0)
          component_of_root[r] = components++;
        vertex_component[i] = component_of_root[r];
      }
    component_reach_.assign (components, 0.0);
    for (const auto& t : faces_)
    {
      const int c = vertex_component[t[0]];
      for (int k = 0; k < 3; ++k)
        component_reach_[c] = std::max (component_reach_[c], (vertices_[t[k]] - vertices_[t[(k + 1) % 3]]).norm ());
    }
    component_offsets_.assign (components + 1, 0);
    for (int i = 0; i < n; ++i)
      if (vertex_component[i] >= 0)
        ++component_offsets_[vertex_component[i] + 1];
    for (int c = 0; c < components; ++c)
      component_offsets_[c + 1] += component_offsets_[c];
    face_vertices_.assign (component_offsets_[components], -1);
    {
      std::vector<int> fill_c (component_offsets_.begin (), component_offsets_.end () - 1);
      for (int i = 0; i < n; ++i)
        if (vertex_component[i] >= 0)
          face_vertices_[fill_c[vertex_component[i]]++] = i;
    }

    local_.assign (n, Eigen::Vector3d::Zero ());
    local_stamp_.assign (n, 0);
    face_stamp_.assign (nf, 0);
    stamp_ = 0;
  }

  void
  TensorSurfaceGrid::setGrowthMargin (double fraction)
  {
    if (!(fraction >= 0.0) || !std::isfinite (fraction))
      PCL_TENSOR_THROW (BadArgumentException, "[pcl::TensorSurfaceGrid::setGrowthMargin] " << fraction
                        << " must be non-negative and finite");
    growth_margin_fraction_ = fraction;
  }

  void
  TensorSurfaceGrid::setGrid (int grid_size, double bin_size)
  {
    if (grid_size < 1 || grid_size > TENSOR_MAX_GRID_SIZE)
      PCL_TENSOR_THROW (BadArgumentException, "[pcl::TensorSurfaceGrid::setGrid] grid size N = " << grid_size
                        << " is outside [1, " << TENSOR_MAX_GRID_SIZE << "]");
    if (!(bin_size > 0.0) || !std::isfinite (bin_size))
      PCL_TENSOR_THROW (BadArgumentException, "[pcl::TensorSurfaceGrid::setGrid] bin size " << bin_size
                        << " must be positive and finite");
    grid_size_ = grid_size;
    bin_size_ = bin_size;
    inv_bin_size_ = 1.0 / bin_size;
    dense_.assign (static_cast<std::size_t> (grid_size) * grid_size * grid_size, 0.0);
    touched_bits_.assign ((dense_.size () + 63) / 64, 0);
    touched_.clear ();
  }

  const Eigen::Vector3d&
  TensorSurfaceGrid::localVertex (int v)
  {
    if (local_stamp_[v] != stamp_)
    {
      local_[v] = frame_ * (vertices_[v] - origin_);
      local_stamp_[v] = stamp_;
    }
    return local_[v];
  }

  template <int axis> void
  TensorSurfaceGrid::split (const Polygon& in, double plane, Polygon& below, Polygon& above)
  {
    // One Sutherland-Hodgman step against the plane u_axis = plane, keeping both sides. The inputs are
    // convex (a triangle cut by at most six axis-aligned planes), so each side has at most 9 vertices.
    below.n = 0;
    above.n = 0;
    const int n = in.n;
    // Rounding could make a nearly degenerate polygon cross the plane more than twice; never write
    // past the buffers (such a sliver has no measurable area).
    constexpr int last = Polygon::capacity - 2;
    const double* prev = in.p[n - 1];
    double dp = prev[axis] - plane;
    for (int i = 0; i < n; ++i)
    {
      const double* cur = in.p[i];
      const double dc = cur[axis] - plane;
      if (below.n > last || above.n > last)
        break;
      if ((dp < 0.0 && dc > 0.0) || (dp > 0.0 && dc < 0.0))
      {
        const double t = dp / (dp - dc);
        double* qb = below.p[below.n++];
        double* qa = above.p[above.n++];
        for (int k = 0; k < 3; ++k)
          qb[k] = qa[k] = prev[k] + t * (cur[k] - prev[k]);
        qb[axis] = qa[axis] = plane;
      }
      if (dc <= 0.0)
      {
        double* q = below.p[below.n++];
        q[0] = cur[0]; q[1] = cur[1]; q[2] = cur[2];
      }
      if (dc >= 0.0)
      {
        double* q = above.p[above.n++];
        q[0] = cur[0]; q[1] = cur[1]; q[2] = cur[2];
      }
      prev = cur;
      dp = dc;
    }
  }

  void
  TensorSurfaceGrid::addArea (const Polygon& poly, int bin)
  {
    if (poly.n < 3)
      return;
    // The fan's area on the projection (about the first vertex, for precision); the pieces lie in the
    // face's plane, so it is their area times |n_w|.
    const int u = area_u_, v = area_v_;
    const double ou = poly.p[0][u], ov = poly.p[0][v];
    double twice = 0.0;
    for (int i = 1; i + 1 < poly.n; ++i)
      twice += (poly.p[i][u] - ou) * (poly.p[i + 1][v] - ov) - (poly.p[i + 1][u] - ou) * (poly.p[i][v] - ov);
    const double area = area_scale_ * std::abs (twice);
    if (!(area > 0.0))
      return;
    touched_bits_[static_cast<std::size_t> (bin) >> 6] |= std::uint64_t (1) << (bin & 63);
    dense_[bin] += area;
  }

  template <int axis> void
  TensorSurfaceGrid::sweep (const Polygon& poly, int flat_prefix)
  {
    if (poly.n < 3)
      return;
    double lo = poly.p[0][axis], hi = lo;
    for (int i = 1; i < poly.n; ++i)
    {
      lo = std::min (lo, poly.p[i][axis]);
      hi = std::max (hi, poly.p[i][axis]);
    }
    const int n = grid_size_;
    const double half_bins = 0.5 * n;
    if (hi <= -half_extent_ || lo >= half_extent_)
      return;
    // Bin range; the clamp to [-1, n] keeps the truncating cast a floor.
    const double x0 = std::min (std::max (lo * inv_bin_size_ + half_bins, -1.0), static_cast<double> (n));
    const double x1 = std::min (std::max (hi * inv_bin_size_ + half_bins, -1.0), static_cast<double> (n));
    const int i0 = std::max (static_cast<int> (x0 + 2.0) - 2, 0);
    const int i1 = std::min (static_cast<int> (x1 + 2.0) - 2, n - 1);

    // Cut the polygon slab by slab; the remainder alternates between two buffers (no copies).
    Polygon buffers[2], below;
    int next = 0;
    const Polygon* rem = &poly;
    const double lower_plane = (i0 - half_bins) * bin_size_;
    if (lo < lower_plane)
    {
      split<axis> (*rem, lower_plane, below, buffers[next]);
      rem = &buffers[next];
      next ^= 1;
    }
    for (int i = i0; i <= i1; ++i)
    {
      const double plane = (i + 1 - half_bins) * bin_size_;
      const Polygon* piece = rem;
      const bool cut = hi > plane;
      if (cut)
      {
        split<axis> (*rem, plane, below, buffers[next]);
        piece = &below;
      }
      if constexpr (axis < 2)
        sweep<axis + 1> (*piece, flat_prefix * n + i);
      else
        addArea (*piece, flat_prefix * n + i);
      if (!cut || i == i1)
        break;
      rem = &buffers[next];
      next ^= 1;
    }
  }

  bool
  TensorSurfaceGrid::visitFace (int face)
  {
    ++stats_.faces_visited;
    const auto& t = faces_[face];
    const Eigen::Vector3d& a = localVertex (t[0]);
    const Eigen::Vector3d& b = localVertex (t[1]);
    const Eigen::Vector3d& c = localVertex (t[2]);
    const Eigen::Vector3d lo = a.cwiseMin (b).cwiseMin (c);
    const Eigen::Vector3d hi = a.cwiseMax (b).cwiseMax (c);
    const double g = half_extent_ + growth_margin_;
    if ((hi.array () <= -g).any () || (lo.array () >= g).any ())
      return false;  // outside the grid and its guard band: the region stops here
    const double h = half_extent_;
    if ((hi.array () <= -h).any () || (lo.array () >= h).any ())
      return true;   // in the guard band: grow through it, nothing to clip
    ++stats_.faces_clipped;
    if (face_normals_[face].isZero ())
      return true;  // degenerate triangle: no area, but it still connects the region
    const Eigen::Vector3d normal = (frame_ * face_normals_[face]).cwiseAbs ();
    int w = 0;
    normal.maxCoeff (&w);
    area_u_ = (w + 1) % 3;
    area_v_ = (w + 2) % 3;
    area_scale_ = 0.5 / normal[w];
    Polygon poly;
    poly.n = 3;
    for (int k = 0; k < 3; ++k)
    {
      poly.p[0][k] = a[k];
      poly.p[1][k] = b[k];
      poly.p[2][k] = c[k];
    }
    sweep<0> (poly, 0);
    return true;
  }

  void
  TensorSurfaceGrid::computeBins (const Eigen::Vector3d& origin, const Eigen::Matrix3d& frame, int seed_a,
                                  int seed_b, std::vector<std::uint16_t>& bin_index, std::vector<float>& bin_area)
  {
    if (faces_.empty ())
      PCL_TENSOR_THROW (InvalidScanException, "[pcl::TensorSurfaceGrid::computeBins] no mesh set");
    if (!(bin_size_ > 0.0))
      PCL_TENSOR_THROW (BadArgumentException, "[pcl::TensorSurfaceGrid::computeBins] no grid set");
    origin_ = origin;
    frame_ = frame;
    half_extent_ = 0.5 * grid_size_ * bin_size_;
    growth_margin_ = region_growing_ ? growth_margin_fraction_ * half_extent_ : 0.0;
    stats_ = Stats ();
    if (++stamp_ == 0)
    {
      std::fill (local_stamp_.begin (), local_stamp_.end (), 0u);
      std::fill (face_stamp_.begin (), face_stamp_.end (), 0u);
      stamp_ = 1;
    }

    if (region_growing_)
    {
      queue_.clear ();
      auto push_faces_of = [this] (int v)
      {
        for (int k = vertex_face_offsets_[v]; k < vertex_face_offsets_[v + 1]; ++k)
        {
          const int g = vertex_faces_[k];
          if (face_stamp_[g] != stamp_)
          {
            face_stamp_[g] = stamp_;
            queue_.push_back (g);
          }
        }
      };
      // Seed: the vertex closest to the origin (Section 2), and the two pair vertices. With
      // seed_every_component_, also the closest vertex of every other component that can reach the
      // grid: a triangle meets the cube only if each of its vertices lies within its longest edge of a
      // point of the cube, i.e. within h sqrt(3) + longest edge of the origin.
      const double cube_radius = (half_extent_ + growth_margin_) * std::sqrt (3.0);
      int best_vertex = -1;
      double best_d2 = std::numeric_limits<double>::infinity ();
      for (int c = 0; c + 1 < static_cast<int> (component_offsets_.size ()); ++c)
      {
        int closest = -1;
        double closest_d2 = std::numeric_limits<double>::infinity ();
        for (int k = component_offsets_[c]; k < component_offsets_[c + 1]; ++k)
        {
          const double d2 = (vertices_[face_vertices_[k]] - origin).squaredNorm ();
          if (d2 < closest_d2)
          {
            closest_d2 = d2;
            closest = face_vertices_[k];
          }
        }
        if (closest_d2 < best_d2)
        {
          best_d2 = closest_d2;
          best_vertex = closest;
        }
        const double reach = cube_radius + component_reach_[c];
        if (seed_every_component_ && closest_d2 <= reach * reach)
          push_faces_of (closest);
      }
      if (best_vertex >= 0)
        push_faces_of (best_vertex);
      const int nv = static_cast<int> (vertices_.size ());
      if (seed_a >= 0 && seed_a < nv)
        push_faces_of (seed_a);
      if (seed_b >= 0 && seed_b < nv)
        push_faces_of (seed_b);
      for (std::size_t head = 0; head < queue_.size (); ++head)
      {
        const int f = queue_[head];
        if (!visitFace (f))
          continue;  // completely outside the grid (and guard band): the region stops here
        for (const int v : faces_[f])
          push_faces_of (v);
      }
    }
    else
    {
      const double reach = half_extent_ * std::sqrt (3.0);
      for (std::size_t f = 0; f < faces_.size (); ++f)
      {
        const double r = face_radii_[f] + reach;
        if ((face_centres_[f] - origin).squaredNorm () > r * r)
          continue;
        visitFace (static_cast<int> (f));
      }
    }

    // Sorted bin order from the bitmap of touched bins (cheaper than sorting them).
    touched_.clear ();
    for (std::size_t w = 0; w < touched_bits_.size (); ++w)
    {
      std::uint64_t bits = touched_bits_[w];
      touched_bits_[w] = 0;
      while (bits)
      {
        touched_.push_back (static_cast<int> (w * 64 + static_cast<std::size_t> (__builtin_ctzll (bits))));
        bits &= bits - 1;
      }
    }
    const double min_area = 1e-12 * bin_size_ * bin_size_;
    bin_index.clear ();
    bin_area.clear ();
    std::size_t kept = 0;
    for (const int b : touched_)
      if (dense_[b] > min_area)
        ++kept;
    bin_index.reserve (kept);
    bin_area.reserve (kept);
    for (const int b : touched_)
    {
      if (dense_[b] > min_area)
      {
        bin_index.push_back (static_cast<std::uint16_t> (b));
        bin_area.push_back (static_cast<float> (dense_[b]));
      }
      dense_[b] = 0.0;
    }
    touched_.clear ();
  }
}
