/*
 * pcl_tensor: 2D Delaunay triangulation of the retinal plane (private to the library).
 */
#include "delaunay_2d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace pcl
{
  namespace detail
  {
    namespace
    {
      /** p, q, r turn counter-clockwise (within the rounding of the test). */
      bool
      counterClockwise (const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r)
      {
        return (q.y () - p.y ()) * (r.x () - q.x ()) - (q.x () - p.x ()) * (r.y () - q.y ()) < 0.0;
      }

      /** p lies inside the circle through a, b, c (a, b, c clockwise in this sweep's convention). */
      bool
      inCircle (const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, const Eigen::Vector2d& p)
      {
        const double dx = a.x () - p.x (), dy = a.y () - p.y ();
        const double ex = b.x () - p.x (), ey = b.y () - p.y ();
        const double fx = c.x () - p.x (), fy = c.y () - p.y ();
        const double ap = dx * dx + dy * dy, bp = ex * ex + ey * ey, cp = fx * fx + fy * fy;
        return dx * (ey * cp - bp * fy) - dy * (ex * cp - bp * fx) + ap * (ex * fy - ey * fx) < 0.0;
      }

      /** The centre of the circle through a, b, c, relative to a; infinite for collinear points. */
      Eigen::Vector2d
      circumcentreOffset (const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c)
      {
        const Eigen::Vector2d d = b - a, e = c - a;
        const double bl = d.squaredNorm (), cl = e.squaredNorm ();
        const double k = 0.5 / (d.x () * e.y () - d.y () * e.x ());
        return {(e.y () * bl - d.y () * cl) * k, (d.x () * cl - e.x () * bl) * k};
      }

      /** A monotone stand-in for the angle of (dx, dy), in [0, 1): cheaper than atan2. */
      double
      pseudoAngle (double dx, double dy)
      {
        const double p = dx / (std::abs (dx) + std::abs (dy));
        return (dy > 0.0 ? 3.0 - p : 1.0 + p) / 4.0;
      }

      constexpr std::int32_t kNone = -1;

      /** The sweep: triangles_ as index triples, halfedges_[e] the opposite half-edge (or kNone on the hull). */
      class Sweep
      {
        public:
          explicit Sweep (const std::vector<Eigen::Vector2d>& points)
            : p_ (points), n_ (static_cast<std::int32_t> (points.size ())),
              hash_size_ (static_cast<std::int32_t> (std::ceil (std::sqrt (static_cast<double> (points.size ()))))),
              hull_prev_ (points.size ()), hull_next_ (points.size ()), hull_tri_ (points.size ()),
              hull_hash_ (static_cast<std::size_t> (std::max (hash_size_, 1)), kNone)
          {
            const std::size_t max_triangles = points.size () > 2 ? 2 * points.size () - 5 : 0;
            triangles_.reserve (3 * max_triangles);
            halfedges_.reserve (3 * max_triangles);
          }

          std::vector<std::int32_t>
          run ()
          {
            std::int32_t i0, i1, i2;
            if (n_ < 3 || !seed (i0, i1, i2))
              return {};
            std::vector<std::int32_t> ids (static_cast<std::size_t> (n_));
            std::iota (ids.begin (), ids.end (), 0);
            std::vector<double> dist (static_cast<std::size_t> (n_));
            for (std::int32_t i = 0; i < n_; ++i)
              dist[i] = (p_[i] - centre_).squaredNorm ();
            std::stable_sort (ids.begin (), ids.end (), [&] (std::int32_t a, std::int32_t b) { return dist[a] < dist[b]; });
            startHull (i0, i1, i2);
            Eigen::Vector2d previous (std::numeric_limits<double>::quiet_NaN (), 0.0);
            for (std::size_t k = 0; k < ids.size (); ++k)
            {
              const std::int32_t i = ids[k];
              const Eigen::Vector2d& x = p_[i];
              // A near-duplicate of the point before it in the sweep is left out.
              const bool repeat = k > 0 && std::abs (x.x () - previous.x ()) <= kEpsilon && std::abs (x.y () - previous.y ()) <= kEpsilon;
              previous = x;
              if (repeat || i == i0 || i == i1 || i == i2)
                continue;
              addPoint (i);
            }
            return triangles_;
          }

        private:
          static constexpr double kEpsilon = 2.220446049250313e-16;

          /** The seed triangle: the point nearest the centre of the box, its nearest neighbour, and
            * the point making the smallest circle with them. \return false when all are collinear */
          bool
          seed (std::int32_t& i0, std::int32_t& i1, std::int32_t& i2)
          {
            Eigen::Vector2d low = p_[0], high = p_[0];
            for (const auto& q : p_)
            {
              low = low.cwiseMin (q);
              high = high.cwiseMax (q);
            }
            const Eigen::Vector2d middle = 0.5 * (low + high);
            i0 = nearest (middle, kNone);
            i1 = nearest (p_[i0], i0);
            double smallest = std::numeric_limits<double>::infinity ();
            i2 = kNone;
            for (std::int32_t i = 0; i < n_; ++i)
            {
              if (i == i0 || i == i1)
                continue;
              const double r = circumcentreOffset (p_[i0], p_[i1], p_[i]).squaredNorm ();
              if (r < smallest)
              {
                i2 = i;
                smallest = r;
              }
            }
            if (i1 == kNone || i2 == kNone || !std::isfinite (smallest))
              return false;
            if (counterClockwise (p_[i0], p_[i1], p_[i2]))
              std::swap (i1, i2);
            centre_ = p_[i0] + circumcentreOffset (p_[i0], p_[i1], p_[i2]);
            return true;
          }

          /** The point nearest \a q other than \a skip (and at a positive distance from it). */
          std::int32_t
          nearest (const Eigen::Vector2d& q, std::int32_t skip) const
          {
            std::int32_t best = kNone;
            double best_distance = std::numeric_limits<double>::infinity ();
            for (std::int32_t i = 0; i < n_; ++i)
            {
              const double d = (p_[i] - q).squaredNorm ();
              if (i != skip && d < best_distance && (skip == kNone || d > 0.0))
              {
                best = i;
                best_distance = d;
              }
            }
            return best;
          }

          std::int32_t
          hashKey (const Eigen::Vector2d& q) const
          {
            const double angle = pseudoAngle (q.x () - centre_.x (), q.y () - centre_.y ());
            return static_cast<std::int32_t> (std::floor (angle * hash_size_)) % hash_size_;
          }

          void
          startHull (std::int32_t i0, std::int32_t i1, std::int32_t i2)
          {
            hull_start_ = i0;
            hull_next_[i0] = hull_prev_[i2] = i1;
            hull_next_[i1] = hull_prev_[i0] = i2;
            hull_next_[i2] = hull_prev_[i1] = i0;
            hull_tri_[i0] = 0;
            hull_tri_[i1] = 1;
            hull_tri_[i2] = 2;
            for (const std::int32_t i : {i0, i1, i2})
              hull_hash_[hashKey (p_[i])] = i;
            addTriangle (i0, i1, i2, kNone, kNone, kNone);
          }

          /** A hull edge that \a i sees (kNone for a near-duplicate of a hull point), found from the hash
            * of its angle about the centre; \a first says whether it is the first edge the walk tried. */
          std::int32_t
          visibleEdge (std::int32_t i, bool& first) const
          {
            std::int32_t start = 0;
            const std::int32_t key = hashKey (p_[i]);
            for (std::int32_t j = 0; j < hash_size_; ++j)
            {
              start = hull_hash_[(key + j) % hash_size_];
              if (start != kNone && start != hull_next_[start])
                break;
            }
            start = hull_prev_[start];
            std::int32_t e = start;
            while (!counterClockwise (p_[i], p_[e], p_[hull_next_[e]]))
            {
              e = hull_next_[e];
              if (e == start)
                return kNone;
            }
            first = e == start;
            return e;
          }

          /** Connect \a i to every hull edge it sees, flipping to keep the triangulation Delaunay. */
          void
          addPoint (std::int32_t i)
          {
            bool first = false;
            std::int32_t e = visibleEdge (i, first);
            if (e == kNone)
              return;
            std::int32_t t = addTriangle (e, i, hull_next_[e], kNone, kNone, hull_tri_[e]);
            hull_tri_[i] = legalize (t + 2);
            hull_tri_[e] = t;
            // Forward along the hull, while the point sees the next edge too.
            std::int32_t n = hull_next_[e];
            for (std::int32_t q = hull_next_[n]; counterClockwise (p_[i], p_[n], p_[q]); q = hull_next_[n])
            {
              t = addTriangle (n, i, q, hull_tri_[i], kNone, hull_tri_[n]);
              hull_tri_[i] = legalize (t + 2);
              hull_next_[n] = n;  // removed from the hull
              n = q;
            }
            // Backward, when the first edge tried was visible (the visible run may start before it).
            if (first)
              for (std::int32_t q = hull_prev_[e]; counterClockwise (p_[i], p_[q], p_[e]); q = hull_prev_[e])
              {
                t = addTriangle (q, i, e, kNone, hull_tri_[e], hull_tri_[q]);
                legalize (t + 2);
                hull_tri_[q] = t;
                hull_next_[e] = e;
                e = q;
              }
            hull_start_ = hull_prev_[i] = e;
            hull_next_[e] = hull_prev_[n] = i;
            hull_next_[i] = n;
            hull_hash_[hashKey (p_[i])] = i;
            hull_hash_[hashKey (p_[e])] = e;
          }

          std::int32_t
          addTriangle (std::int32_t i0, std::int32_t i1, std::int32_t i2, std::int32_t a, std::int32_t b, std::int32_t c)
          {
            const auto t = static_cast<std::int32_t> (triangles_.size ());
            triangles_.insert (triangles_.end (), {i0, i1, i2});
            halfedges_.insert (halfedges_.end (), {kNone, kNone, kNone});
            link (t, a);
            link (t + 1, b);
            link (t + 2, c);
            return t;
          }

          void
          link (std::int32_t a, std::int32_t b)
          {
            halfedges_[a] = b;
            if (b != kNone)
              halfedges_[b] = a;
          }

          /** Flip edge \a a and the edges it uncovers until every pair of triangles is Delaunay.
            * \return the half-edge that replaced a's predecessor */
          std::int32_t
          legalize (std::int32_t a)
          {
            std::vector<std::int32_t>& stack = edge_stack_;
            stack.clear ();
            std::int32_t ar = 0;
            while (true)
            {
              const std::int32_t b = halfedges_[a];
              const std::int32_t a0 = a - a % 3;
              ar = a0 + (a + 2) % 3;
              if (b == kNone)
              {
                if (stack.empty ())
                  break;
                a = stack.back ();
                stack.pop_back ();
                continue;
              }
              const std::int32_t b0 = b - b % 3, al = a0 + (a + 1) % 3, bl = b0 + (b + 2) % 3;
              const std::int32_t p0 = triangles_[ar], pr = triangles_[a], pl = triangles_[al], p1 = triangles_[bl];
              if (!inCircle (p_[p0], p_[pr], p_[pl], p_[p1]))
              {
                if (stack.empty ())
                  break;
                a = stack.back ();
                stack.pop_back ();
                continue;
              }
              triangles_[a] = p1;
              triangles_[b] = p0;
              const std::int32_t hbl = halfedges_[bl];
              if (hbl == kNone)
                fixHullTriangle (bl, a);  // the flipped edge lay on the hull (rare)
              link (a, hbl);
              link (b, halfedges_[ar]);
              link (ar, bl);
              stack.push_back (b0 + (b + 1) % 3);
            }
            return ar;
          }

          void
          fixHullTriangle (std::int32_t from, std::int32_t to)
          {
            std::int32_t e = hull_start_;
            do
            {
              if (hull_tri_[e] == from)
              {
                hull_tri_[e] = to;
                return;
              }
              e = hull_prev_[e];
            } while (e != hull_start_);
          }

          const std::vector<Eigen::Vector2d>& p_;
          const std::int32_t n_;
          const std::int32_t hash_size_;
          Eigen::Vector2d centre_ = Eigen::Vector2d::Zero ();
          std::vector<std::int32_t> hull_prev_, hull_next_, hull_tri_, hull_hash_;
          std::int32_t hull_start_ = 0;
          std::vector<std::int32_t> triangles_, halfedges_, edge_stack_;
      };
    }

    std::vector<std::array<std::int32_t, 3>>
    delaunayTriangulation (const std::vector<Eigen::Vector2d>& points)
    {
      const std::vector<std::int32_t> flat = Sweep (points).run ();
      std::vector<std::array<std::int32_t, 3>> triangles;
      triangles.reserve (flat.size () / 3);
      for (std::size_t t = 0; t + 2 < flat.size (); t += 3)
      {
        std::array<std::int32_t, 3> tri{flat[t], flat[t + 1], flat[t + 2]};
        const Eigen::Vector2d e1 = points[tri[1]] - points[tri[0]], e2 = points[tri[2]] - points[tri[0]];
        if (e1.x () * e2.y () - e1.y () * e2.x () < 0.0)
          std::swap (tri[1], tri[2]);
        triangles.push_back (tri);
      }
      return triangles;
    }
  }
}
