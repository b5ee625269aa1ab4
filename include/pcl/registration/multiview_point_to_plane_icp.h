/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_mesh.h>

#include <Eigen/Geometry>

#include <functional>
#include <utility>
#include <vector>

namespace pcl
{
  namespace registration
  {
    /** \brief Poses of several views: each maps its view's points into the common frame. */
    using ViewPoses = std::vector<Eigen::Affine3d, Eigen::aligned_allocator<Eigen::Affine3d>>;

    /** \brief Pairs of views (i, j) that overlap. */
    using ViewPairs = std::vector<std::pair<int, int>>;

    /** \brief Settings of multiviewPointToPlaneIcp(); distances in units of d_res.
      * \note The paper's global registration is Williams and Bennamoun's, without these settings; the
      * defaults are ours (doc/design.md#multiview-point-to-plane-icp). */
    struct MultiviewIcpParams
    {
      /** Iterations at most (each re-pairs every overlapping pair, then moves all views at once). */
      int max_iterations = 30;
      /** Pairs of points farther apart than this are not used. */
      double max_distance = 4.0;
      /** Points sampled evenly from each view, for each of its overlapping pairs. */
      int sample_points = 1000;
      /** Paired points whose normals differ by more than this (degrees) are not used. */
      double max_normal_angle = 45.0;
      /** Points on the boundary of a view's mesh are not used as partners: near the edge of the
        * overlap their nearest point is on the boundary rather than on the same surface (Turk and
        * Levoy, 1994). */
      bool skip_boundary = true;
      /** Stop when no view turns more than this (degrees) ... */
      double min_rotation = 1e-2;
      /** ... and none moves more than this (d_res). Both lie well under the scans' noise and above the
        * limit cycle in which re-pairing leaves the views (doc/design.md#multiview-point-to-plane-icp). */
      double min_translation = 1e-2;
    };

    /** \brief What multiviewPointToPlaneIcp() did. */
    struct MultiviewIcpResult
    {
      ViewPoses poses;
      int iterations = 0;
      std::size_t pairs = 0;       ///< point pairs used in the last iteration
      double rms_before = 0.0;     ///< RMS point-to-plane distance of the first iteration's pairs
      double rms_after = 0.0;      ///< ... and of the last iteration's, in the units of the points
    };

    /** \brief Called after each iteration with (iteration, max_iterations). */
    using MultiviewIcpProgress = std::function<void (int iteration, int max_iterations)>;

    /** \brief Simultaneous multiview registration: point-to-plane ICP over every overlapping pair at
      * once, in the spirit of Williams and Bennamoun (2001), the global registration of Mian et al.
      * (Section 5, module 5 of Fig. 9). Each iteration pairs sampled points of each view with their
      * nearest points on each overlapping view (both directions), linearises every pair's
      * point-to-plane distance in all poses together, and solves one least-squares system for a small
      * motion of every view but the fixed one. The residual error of a chain of pairwise registrations
      * (a turntable's loop that does not close) is thus spread over all views.
      * \param[in] views the fine meshes M_i, with normals (NaN or zero normals are not used)
      * \param[in] initial each view's pose into the common frame (e.g. from pairwise registration)
      * \param[in] pairs the overlapping pairs; views in no pair keep their initial pose
      * \param[in] fixed the view that does not move (it defines the common frame)
      * \param[in] resolution d_res, the unit of the distances in \a params
      * \param[in] params iterations, distances, sampling
      * \param[in] progress optional, called after each iteration
      * \param[in] threads threads for the pairs (0: every core); the result is the same for any number
      * \throw pcl::BadArgumentException on sizes that do not agree, a pair or fixed view out of range,
      * or non-positive distances
      */
    MultiviewIcpResult
    multiviewPointToPlaneIcp (const std::vector<const ScanMesh*>& views, const ViewPoses& initial, const ViewPairs& pairs,
                              int fixed, double resolution, const MultiviewIcpParams& params,
                              const MultiviewIcpProgress& progress = {}, unsigned threads = 1);

    /** \brief The same with several views that do not move, e.g. those of a model being extended,
      * whose poses were settled before: only the others move, and \a fixed[i] views keep \a initial[i]
      * exactly.
      * \throw pcl::BadArgumentException as above, or when no view is fixed
      */
    MultiviewIcpResult
    multiviewPointToPlaneIcp (const std::vector<const ScanMesh*>& views, const ViewPoses& initial, const ViewPairs& pairs,
                              const std::vector<bool>& fixed, double resolution, const MultiviewIcpParams& params,
                              const MultiviewIcpProgress& progress = {}, unsigned threads = 1);

    /** \brief The pairs of views that overlap under the given poses: at least \a min_fraction of the
      * sampled points of the smaller view have a point of the other within \a max_distance d_res.
      * \param[in] views fine meshes
      * \param[in] poses their poses; views with \a use[i] false are left out
      * \param[in] use which views take part (empty: all)
      * \param[in] resolution d_res
      * \param[in] max_distance pairing distance in d_res
      * \param[in] min_fraction overlap needed, in (0, 1]
      * \param[in] sample_points points sampled per view
      * \param[in] threads threads for the pairs (0: every core)
      * \param[out] fractions if given, each returned pair's overlap fraction
      * \return pairs (i < j), sorted
      */
    ViewPairs
    findOverlappingViews (const std::vector<const ScanMesh*>& views, const ViewPoses& poses, const std::vector<bool>& use,
                          double resolution, double max_distance, double min_fraction, int sample_points = 500,
                          unsigned threads = 1, std::vector<double>* fractions = nullptr);

    /** \brief findOverlappingViews() over the given \a candidates only (pairs of two given views, in any order),
      * e.g. the pairs that involve a view added to views settled before.
      * \return the candidates that overlap, in the order given
      */
    ViewPairs
    selectOverlappingPairs (const std::vector<const ScanMesh*>& views, const ViewPoses& poses, const ViewPairs& candidates,
                          double resolution, double max_distance, double min_fraction, int sample_points = 500,
                          unsigned threads = 1, std::vector<double>* fractions = nullptr);
  }
}
