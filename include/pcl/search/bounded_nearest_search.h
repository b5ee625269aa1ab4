/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/memory.h>
#include <pcl/point_cloud.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace pcl
{
  /** \brief Exact nearest-neighbour queries within a bounded radius, on a uniform grid of cells.
    *
    * Local verification (Section 4.1 of Mian et al.) and its ICP ask one question tens of thousands of
    * times per hypothesis: "which point of this view is nearest to q, if any lies within r?", with r a
    * few d_res. A kd-tree answers any radius, so it descends and backtracks for each query. Here the
    * radius is known, so the answer lies in the few grid cells that the ball of radius r meets: they are
    * scanned and nothing else. The answer is exact, the same nearest squared distance a kd-tree returns;
    * of points at exactly the same distance the one with the lower index is returned.
    *
    * Points are sorted by cell (a counting sort over a dense grid, x fastest), so the cells of one grid
    * row that a ball meets hold one contiguous run of points, scanned four at a time with SSE2 where
    * the compiler has it (each lane's distance is the scalar one, bit for bit). Any radius can be
    * asked; a query scans about (2 r + cell)^2 / d_res^2 points of a surface, so the cell should be
    * near the radii asked; nearest() asks half a cell first and the whole radius only when that finds
    * nothing, and a hinted nearest() only the ball through its last answer.
    * The dense grid has at most max(4096, 4 n) cells for n points: when the bounding box needs more,
    * the cells are made larger (getCellSize()) and the answers stay exact.
    * \ingroup search
    */
  class BoundedNearestSearch
  {
    public:
      using Ptr = shared_ptr<BoundedNearestSearch>;
      using ConstPtr = shared_ptr<const BoundedNearestSearch>;

      /** \brief An empty search; setInputCloud() or setPoints() fills it.
        * \param[in] cell_size the wanted edge of a grid cell (> 0 and finite; see the class comment)
        * \throw pcl::BadArgumentException otherwise
        */
      explicit BoundedNearestSearch (float cell_size = 1.0f);

      /** \brief Index the xyz of \a cloud; point i of the cloud is answered as index i. Non-finite
        * points are never answered. */
      template <typename PointT> void
      setInputCloud (const pcl::PointCloud<PointT>& cloud)
      {
        std::vector<Eigen::Vector3f> points (cloud.size ());
        for (std::size_t i = 0; i < cloud.size (); ++i)
          points[i] = cloud[i].getVector3fMap ();
        setPoints (points);
      }

      /** \brief Index \a points (non-finite ones are skipped but keep their positions as indices).
        * \throw pcl::BadArgumentException when there are 2^31 points or more */
      void setPoints (const std::vector<Eigen::Vector3f>& points);

      /** \brief The nearest indexed point within \a radius of \a query (distance <= radius).
        * \param[in] query the query point; a non-finite one has no neighbour
        * \param[in] radius the largest distance accepted
        * \param[out] sqr_distance its squared distance (left unchanged when there is none)
        * \return its index, or -1 when no point lies within \a radius
        */
      int nearest (const Eigen::Vector3f& query, float radius, float& sqr_distance) const;

      /** \brief nearest() for a query asked again after a small move, as ICP asks each of its points once
        * per iteration: the point found last time (\a hint, in and out; -1 to start) bounds the search to
        * the ball through it, which holds the answer and is mostly one cell. The answer is the same as
        * nearest()'s. */
      int nearest (const Eigen::Vector3f& query, float radius, float& sqr_distance, std::int32_t& hint) const;

      /** \brief Whether any indexed point lies within \a radius of \a query (stops at the first found). */
      bool anyWithin (const Eigen::Vector3f& query, float radius) const;

      /** \brief anyWithin() for a run of nearby queries: the point found last (\a hint, in and out;
        * -1 to start) is tried before the cells. Successive points of a scan line mostly share it, so
        * counting a whole view's correspondences scans the cells for few of them. The answer is the
        * same as anyWithin()'s. */
      bool anyWithin (const Eigen::Vector3f& query, float radius, std::int32_t& hint) const;

      /** \brief Every indexed point within \a radius of \a query, in ascending index order (so that
        * sums over them do not depend on the grid).
        * \return the number of points found */
      std::size_t radiusSearch (const Eigen::Vector3f& query, float radius, std::vector<int>& indices) const;

      /** \brief Number of points indexed (the finite ones). */
      std::size_t size () const { return index_.size (); }

      /** \brief The cell edge in use: the one asked for, or larger when the grid had to be bounded. */
      float getCellSize () const { return cell_; }

    private:
      class Distances;

      /** Cell ranges [lo, hi] met by the ball; false when it misses the grid or is not finite. */
      bool cellRange (const Eigen::Vector3f& query, float radius, int lo[3], int hi[3]) const;

      /** The stored position of the nearest point at a squared distance of at most \a bound, scanning the
        * cells within \a radius (sqrt (bound) or more), or -1. */
      std::int32_t nearestWithin (const Eigen::Vector3f& query, float radius, float bound, float& sqr_distance) const;

      /** nearest() as a stored position, or -1. */
      std::int32_t nearestPosition (const Eigen::Vector3f& query, float radius, float& sqr_distance) const;

      /** Calls \a visit (first, last), a range of stored positions, for each row of cells the ball
        * meets; stops when it returns true. */
      template <typename Visit> bool forEachRow (const Eigen::Vector3f& query, float radius, Visit&& visit) const;

      float wanted_cell_, cell_, inv_cell_ = 1.0f;
      float slack_ = 0.0f;  ///< a few float roundings of the largest coordinate
      Eigen::Vector3f origin_ = Eigen::Vector3f::Zero ();
      int dims_[3] = {0, 0, 0};
      std::vector<std::uint32_t> cell_start_;  ///< CSR: positions of cell c are [cell_start_[c], cell_start_[c + 1])
      // The points in cell order, one array per coordinate so that four are compared at once.
      std::vector<float> x_, y_, z_;
      std::vector<std::int32_t> index_;        ///< each stored point's index in the input
  };
}
