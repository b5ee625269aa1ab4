/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/search/bounded_nearest_search.h>
#include <pcl/common/tensor_exceptions.h>

#include <algorithm>
#include <cmath>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace pcl
{
  BoundedNearestSearch::BoundedNearestSearch (float cell_size) : wanted_cell_ (cell_size), cell_ (cell_size)
  {
    if (!(cell_size > 0.0f) || !std::isfinite (cell_size))
      PCL_TENSOR_THROW (BadArgumentException, "BoundedNearestSearch: the cell size must be positive and finite, got " << cell_size);
  }

  void
  BoundedNearestSearch::setPoints (const std::vector<Eigen::Vector3f>& points)
  {
    if (points.size () >= static_cast<std::size_t> (std::numeric_limits<std::int32_t>::max ()))
      PCL_TENSOR_THROW (BadArgumentException, "BoundedNearestSearch: " << points.size () << " points are too many");
    x_.clear ();
    y_.clear ();
    z_.clear ();
    index_.clear ();
    cell_start_.clear ();
    dims_[0] = dims_[1] = dims_[2] = 0;
    Eigen::Vector3f lo = Eigen::Vector3f::Constant (std::numeric_limits<float>::max ()), hi = -lo;
    std::size_t finite = 0;
    for (const auto& p : points)
      if (p.allFinite ())
      {
        lo = lo.cwiseMin (p);
        hi = hi.cwiseMax (p);
        ++finite;
      }
    if (finite == 0)
      return;

    // The dense grid is bounded by the point count: a surface fills few cells of its bounding box.
    const double max_cells = std::max (4096.0, 4.0 * static_cast<double> (finite));
    const Eigen::Vector3d extent = (hi - lo).cast<double> ();
    double cell = wanted_cell_;
    for (;;)
    {
      double cells = 1.0;
      for (int k = 0; k < 3; ++k)
        cells *= std::floor (extent[k] / cell) + 1.0;
      if (cells <= max_cells)
        break;
      cell *= std::max (1.01, std::cbrt (cells / max_cells));
    }
    cell_ = static_cast<float> (cell);
    inv_cell_ = static_cast<float> (1.0 / cell);
    origin_ = lo;
    // Float rounding of a distance near the radius must not decide which cells are scanned.
    slack_ = 1e-6f * std::max (lo.cwiseAbs ().maxCoeff (), hi.cwiseAbs ().maxCoeff ());
    for (int k = 0; k < 3; ++k)
      dims_[k] = static_cast<int> (std::floor (extent[k] / cell)) + 1;

    const auto cellOf = [this] (const Eigen::Vector3f& p) {
      std::size_t c = 0;
      for (int k = 2; k >= 0; --k)
      {
        const int i = std::min (static_cast<int> ((p[k] - origin_[k]) * inv_cell_), dims_[k] - 1);
        c = c * static_cast<std::size_t> (dims_[k]) + static_cast<std::size_t> (std::max (i, 0));
      }
      return c;
    };
    const std::size_t n_cells = static_cast<std::size_t> (dims_[0]) * dims_[1] * dims_[2];
    cell_start_.assign (n_cells + 1, 0);
    std::vector<std::uint32_t> cell_of (points.size ());
    for (std::size_t i = 0; i < points.size (); ++i)
      if (points[i].allFinite ())
        ++cell_start_[(cell_of[i] = static_cast<std::uint32_t> (cellOf (points[i]))) + 1];
    for (std::size_t c = 0; c < n_cells; ++c)
      cell_start_[c + 1] += cell_start_[c];
    x_.resize (finite);
    y_.resize (finite);
    z_.resize (finite);
    index_.resize (finite);
    std::vector<std::uint32_t> fill (cell_start_.begin (), cell_start_.end () - 1);
    for (std::size_t i = 0; i < points.size (); ++i)
      if (points[i].allFinite ())
      {
        const std::uint32_t k = fill[cell_of[i]]++;
        x_[k] = points[i].x ();
        y_[k] = points[i].y ();
        z_[k] = points[i].z ();
        index_[k] = static_cast<std::int32_t> (i);
      }
  }

  bool
  BoundedNearestSearch::cellRange (const Eigen::Vector3f& query, float radius, int lo[3], int hi[3]) const
  {
    if (index_.empty () || !query.allFinite () || !(radius >= 0.0f))
      return false;
    // A point that the float distance test accepts may lie a rounding error beyond the radius.
    const double reach = static_cast<double> (radius) * (1.0 + 1e-5) + slack_;
    for (int k = 0; k < 3; ++k)
    {
      // In double, compared before any cast: a far query must not overflow the int. Inside [0, dims)
      // truncation is the floor, so no floor() call is needed.
      const double a = (static_cast<double> (query[k]) - reach - origin_[k]) * inv_cell_;
      const double b = (static_cast<double> (query[k]) + reach - origin_[k]) * inv_cell_;
      if (b < 0.0 || a >= dims_[k])
        return false;
      lo[k] = a > 0.0 ? static_cast<int> (a) : 0;
      hi[k] = b < dims_[k] - 1 ? static_cast<int> (b) : dims_[k] - 1;
    }
    return true;
  }

  template <typename Visit> bool
  BoundedNearestSearch::forEachRow (const Eigen::Vector3f& query, float radius, Visit&& visit) const
  {
    int lo[3], hi[3];
    if (!cellRange (query, radius, lo, hi))
      return false;
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
      {
        const std::size_t row = (static_cast<std::size_t> (z) * dims_[1] + y) * dims_[0];
        if (visit (static_cast<std::size_t> (cell_start_[row + lo[0]]), static_cast<std::size_t> (cell_start_[row + hi[0] + 1])))
          return true;
      }
    return false;
  }

  std::int32_t
  BoundedNearestSearch::nearestPosition (const Eigen::Vector3f& query, float radius, float& sqr_distance) const
  {
    // A point near the surface has its nearest neighbour within half a cell: search that small ball
    // first. Whatever it finds is the exact answer (every nearer point lies in it too, ties included),
    // and a converging ICP asks mostly such queries, each then scanning a few cells instead of (2 r /
    // cell)^2 rows of them.
    const float first = 0.5f * cell_;
    if (radius > 2.0f * first)
    {
      const std::int32_t k = nearestWithin (query, first, first * first, sqr_distance);
      if (k >= 0)
        return k;
    }
    return nearestWithin (query, radius, radius * radius, sqr_distance);
  }

  int
  BoundedNearestSearch::nearest (const Eigen::Vector3f& query, float radius, float& sqr_distance) const
  {
    const std::int32_t k = nearestPosition (query, radius, sqr_distance);
    return k >= 0 ? index_[k] : -1;
  }

  /** Distances from one query to the stored points: the scalar one, and four at a time where SSE2 is
    * there, lane for lane the same float operations in the same order (so the same bits). */
  class BoundedNearestSearch::Distances
  {
    public:
      Distances (const BoundedNearestSearch& search, const Eigen::Vector3f& query)
        : x_ (search.x_.data ()), y_ (search.y_.data ()), z_ (search.z_.data ()),
          qx_ (query.x ()), qy_ (query.y ()), qz_ (query.z ())
      {}

      float
      at (std::size_t k) const
      {
        const float dx = x_[k] - qx_, dy = y_[k] - qy_, dz = z_[k] - qz_;
        return dx * dx + dy * dy + dz * dz;
      }

      /** Calls \a visit (k, d2) for each stored point k in [first, last) in order whose squared distance
        * d2 is at most \a bound (); \a bound is read again after every call, and a true return stops. */
      template <typename Bound, typename Visit> bool
      scan (std::size_t first, std::size_t last, Bound&& bound, Visit&& visit) const
      {
        std::size_t k = first;
#if defined(__SSE2__)
        const __m128 qx = _mm_set1_ps (qx_), qy = _mm_set1_ps (qy_), qz = _mm_set1_ps (qz_);
        for (; k + 4 <= last; k += 4)
        {
          const __m128 dx = _mm_sub_ps (_mm_loadu_ps (x_ + k), qx);
          const __m128 dy = _mm_sub_ps (_mm_loadu_ps (y_ + k), qy);
          const __m128 dz = _mm_sub_ps (_mm_loadu_ps (z_ + k), qz);
          const __m128 d2 = _mm_add_ps (_mm_add_ps (_mm_mul_ps (dx, dx), _mm_mul_ps (dy, dy)), _mm_mul_ps (dz, dz));
          int mask = _mm_movemask_ps (_mm_cmple_ps (d2, _mm_set1_ps (bound ())));
          if (mask == 0)
            continue;
          alignas (16) float lanes[4];
          _mm_store_ps (lanes, d2);
          for (; mask != 0; mask &= mask - 1)
          {
            const int lane = __builtin_ctz (static_cast<unsigned> (mask));
            if (lanes[lane] <= bound () && visit (k + lane, lanes[lane]))
              return true;
          }
        }
#endif
        for (; k < last; ++k)
        {
          const float d2 = at (k);
          if (d2 <= bound () && visit (k, d2))
            return true;
        }
        return false;
      }

    private:
      const float *x_, *y_, *z_;
      float qx_, qy_, qz_;
  };

  int
  BoundedNearestSearch::nearest (const Eigen::Vector3f& query, float radius, float& sqr_distance,
                                 std::int32_t& hint) const
  {
    if (hint >= 0 && static_cast<std::size_t> (hint) < index_.size () && query.allFinite ())
    {
      // The last answer is a point within sqrt (bound): the nearest one lies in that ball, ties too.
      const float bound = Distances (*this, query).at (static_cast<std::size_t> (hint));
      if (bound <= radius * radius)
      {
        const std::int32_t k = nearestWithin (query, std::sqrt (bound), bound, sqr_distance);
        if (k >= 0)
        {
          hint = k;
          return index_[k];
        }
      }
    }
    hint = nearestPosition (query, radius, sqr_distance);
    return hint >= 0 ? index_[hint] : -1;
  }

  std::int32_t
  BoundedNearestSearch::nearestWithin (const Eigen::Vector3f& query, float radius, float bound,
                                       float& sqr_distance) const
  {
    const Distances distances (*this, query);
    float best = bound;
    std::int32_t best_k = -1;
    forEachRow (query, radius, [&] (std::size_t first, std::size_t last) {
      return distances.scan (first, last, [&] { return best; }, [&] (std::size_t k, float d2) {
        // Rows are not in index order: a tie goes to the lower index explicitly.
        if (d2 < best || best_k < 0 || index_[k] < index_[best_k])
        {
          best = d2;
          best_k = static_cast<std::int32_t> (k);
        }
        return false;
      });
    });
    if (best_k >= 0)
      sqr_distance = best;
    return best_k;
  }

  bool
  BoundedNearestSearch::anyWithin (const Eigen::Vector3f& query, float radius) const
  {
    std::int32_t hint = -1;
    return anyWithin (query, radius, hint);
  }

  bool
  BoundedNearestSearch::anyWithin (const Eigen::Vector3f& query, float radius, std::int32_t& hint) const
  {
    const Distances distances (*this, query);
    const float r2 = radius * radius;
    if (hint >= 0 && static_cast<std::size_t> (hint) < index_.size () && distances.at (hint) <= r2)
      return true;
    return forEachRow (query, radius, [&] (std::size_t first, std::size_t last) {
      return distances.scan (first, last, [r2] { return r2; }, [&] (std::size_t k, float) {
        hint = static_cast<std::int32_t> (k);
        return true;
      });
    });
  }

  std::size_t
  BoundedNearestSearch::radiusSearch (const Eigen::Vector3f& query, float radius, std::vector<int>& indices) const
  {
    indices.clear ();
    const Distances distances (*this, query);
    const float r2 = radius * radius;
    forEachRow (query, radius, [&] (std::size_t first, std::size_t last) {
      return distances.scan (first, last, [r2] { return r2; }, [&] (std::size_t k, float) {
        indices.push_back (index_[k]);
        return false;
      });
    });
    std::sort (indices.begin (), indices.end ());
    return indices.size ();
  }
}
