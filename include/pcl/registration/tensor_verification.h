/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

namespace pcl
{
  namespace registration
  {
    /** \brief Thresholds of the local verification of Section 4.1 (Fig. 7, steps 4-14), with the
      * paper's values as defaults where it gives one; each field that departs from it says so in a
      * \\note (doc/design.md#departures-from-the-paper). Distances are in units of d_res, the fine
      * meshes' resolution.
      * \ingroup registration
      */
    struct TensorVerificationParams
    {
      /** t_D = mean(D) * this: how far the coarsely registered reduced meshes may exceed D (1/10). */
      double coarse_dimension_fraction = 0.1;
      /** n_c = min(|M_m|, |M_s|) * this: correspondences needed before ICP; twice as many after
        * (default 1/5).
        * \note The paper uses 1/4. True poses of pairs at 0.3-0.5 overlap (Eq. 14) that are well matched
        * where both sensors see fall just short of 2 n_c at 1/4; 1/5 passes them, and the other checks
        * refuse the wrong hypotheses it lets through; see doc/design.md#correspondence-count. */
      double correspondence_fraction = 0.2;
      /** A correspondence before ICP: points within this many d_res (default 6).
        * \note The paper uses 2; a single tensor's frame is several degrees off on real scans, which
        * moves points far from the tensor by several d_res, so 2 rejects most true hypotheses there;
        * see doc/design.md#coarse-correspondence-distance. */
      double coarse_distance = 6.0;
      /** Count the correspondences of both views (default true; false: the scene's points only). The
        * paper turns "pairs of points on M_m and M_s" within the distance into correspondences and needs
        * more than n_c = min(|M_m|, |M_s|)/4, then 2 n_c within d_res. Counted over the scene alone, 2 n_c
        * is half of the smaller view, which no pair under 0.5 overlap (Eq. 14, at 2 d_res) can reach,
        * although Fig. 18 has correct pairs below it. Counting both, a hypothesis is credited with twice
        * the smaller of the two views' counts: after ICP each view needs n_c points within d_res of the
        * other. (Crediting the sum instead let a pose 140 degrees off pass on a synthetic turntable.)
        * \note Departs from a scene-only reading of the paper, which would refuse every pair under 0.5
        * overlap; see doc/design.md#both-views-counted. */
      bool count_both_views = true;
      /** A correspondence after ICP: points within this many d_res (1). */
      double fine_distance = 1.0;
      /** How far the refined registration's combined dimensions may exceed D, in d_res (2) ... */
      double fine_dimension_tolerance = 2.0;
      /** ... or this fraction of mean(D), when larger (default 0.1, the coarse step's t_D). The paper's
        * 2 d_res take D as a tight bound, which Eq. 1 is not for an object that no single view shows
        * whole: the union of two views of a round object exceeds it at the true pose (by up to about
        * a tenth of D on the teapot), while a pose that puts the views side by side exceeds it by far
        * more. 0: the paper's check.
        * \note Departs from the paper; see doc/design.md#dimension-checks-relative-to-d. */
      double fine_dimension_fraction = 0.1;
      /** How many of the largest principal extents the dimension checks compare with D (2 of 3).
        * \note The paper compares all 3; every range image is thin along its line of sight, so Eq. 1's
        * maximum over views of the third extent underestimates the object and correctly aligned pairs
        * exceed it; see doc/design.md#dimension-checks-on-two-extents. */
      int checked_dimensions = 2;
      /** ICP (point-to-plane, Rusinkiewicz and Levoy's variant): iterations at most. */
      int icp_iterations = 20;
      /** ICP: pairs farther apart than this many d_res are not used, in the first stage ... */
      double icp_max_distance = 8.0;
      /** ... halved stage by stage down to this many (8, 4, 2; PointToPlaneIcpParams::final_distance).
        * \note Beyond the paper, which names ICP without stages: one narrow stage does not reach a
        * hypothesis from a single tensor match, and one wide stage ends biased by the parts of the
        * views that do not overlap; see doc/design.md#own-point-to-plane-icp. */
      double icp_final_distance = 2.0;
      /** ICP: a stage k stages before the last pairs every (icp_coarse_stage_step^k)-th sampled point
        * (PointToPlaneIcpParams::coarse_stage_step; 2: the stages at 8, 4 and 2 d_res pair a quarter,
        * a half and all of them). 1: every stage pairs them all.
        * \note Beyond the paper: a coarse stage only has to bring the pose within reach of the next, so
        * it need not pair every point; see doc/design.md#own-point-to-plane-icp. */
      int icp_coarse_stage_step = 2;
      /** ICP: pairs whose normals differ by more than this many degrees are not used
        * (PointToPlaneIcpParams::max_normal_angle; default 60, Rusinkiewicz and Levoy's compatible
        * normals; 180: all are used).
        * \note Beyond the paper: from the exact pose of views far apart, ICP with every pair moved
        * 6-8 degrees away, pulled by points paired across a sharp edge or a thin part; see
        * doc/design.md#compatible-normals. */
      double icp_max_normal_angle = 60.0;
      /** Scene points sampled (evenly, deterministically) for ICP and the count before ICP.
        * \note Beyond the paper, which uses every point: the sample keeps each refuted hypothesis cheap,
        * and the final count is still over every point; see doc/design.md#own-point-to-plane-icp. */
      int sample_points = 1000;
      /** Free space (beyond the paper): after ICP, a point of either view may lie in front of the
        * other view's surface, in space that view's sensor saw empty, by at most this many d_res
        * (or 3 times the two scans' combined noise, PreparedScan::noise, when the scans are noisier).
        * Not ICP's RMS, which a wrong pose inflates itself, so that a bad fit would widen its own
        * tolerance ... */
      double free_space_distance = 2.0;
      /** ... and only this fraction (1%) of the points that the other view saw may do so. Two kinds of
        * point are not counted: one far in front of the surface on its line of sight but beside a surface
        * at its own depth (an occlusion boundary that a pose a little off misses), and one with fewer
        * than a quarter of its neighbours in its own view violating too (noise, not a misplaced surface). Without
        * them true poses reach 1.8% (raw dragon scans) and 2.1% (noise of 1 d_res); turned poses of
        * symmetric objects and views of another, similar object put whole patches there: a refusal
        * over a wrong answer. 1 disables.
        * \note Beyond the paper, as is free_space_distance; see doc/design.md#free-space-check. */
      double free_space_fraction = 0.01;
      /** Empty space (beyond the paper): a point of either view whose line of sight, in the other
        * view's sensor, passes farther than this many d_res from all of that view's surface, through the
        * background around it (RangeViewProjection::markEmptySpace()), lies where that sensor saw
        * nothing, and counts as a free-space violation too. Default 0: off. It needs the sensor's exact
        * geometry and a scan that is not cropped: on the raw dragon_stand scans, at margin 4, it refused
        * 27 of 37 true poses over 0.5 overlap, while on rendered views it refused wrong poses only.
        * \note See doc/design.md#free-space-check. */
      double empty_space_margin = 0.0;
    };

    /** \brief The stage at which a hypothesis failed local verification. */
    enum class TensorVerificationStage
    {
      PASSED,
      COARSE_DIMENSIONS,  ///< max(D'_ms - D) > t_D (Eq. 9 on the reduced meshes)
      COARSE_OVERLAP,     ///< fewer than n_c correspondences within coarse_distance (default 6 d_res; the paper's 2)
      FINE_OVERLAP,       ///< after ICP, fewer than 2 n_c correspondences within d_res
      FINE_DIMENSIONS,    ///< after ICP, max(D_ms - D) above fine_dimension_tolerance d_res and fine_dimension_fraction mean(D)
      FREE_SPACE          ///< after ICP, too many points of one view where the other's sensor saw nothing
    };

    /** \brief What each view shows of the other under a pose, where the other's sensor could see it:
      * the points whose line of sight in the other sensor meets its surface (at a weight above 0: not on
      * its very border) and that are not hidden behind it by more than the free-space margin. Measured on
      * the verification's samples. */
    struct TensorCovisibility
    {
      /** Fraction of the model's and of the scene's points that the other sensor could see. */
      double model_seen = 0.0, scene_seen = 0.0;
      /** Of those, the fraction within fine_distance d_res of the other view's points. */
      double model_matched = 0.0, scene_matched = 0.0;
      /** Of the points within fine_distance d_res of the other view, the fraction that the other's
        * sensor could see: nearly 1 at a true pose, where they lie on the surface it saw. */
      double model_matched_seen = 0.0, scene_matched_seen = 0.0;
    };

    /** \brief verify() measures the free-space violation exactly up to this many times
      * free_space_fraction, the most a rival may show (TensorRegistration's ambiguity check), and stops
      * counting above: most wrong poses put far more of a view in the other's free space. */
    constexpr double kFreeSpaceMeasuredFactor = 5.0;

    /** \brief Number of stages, PASSED included: the size of per-stage counts. */
    constexpr std::size_t kTensorVerificationStages = 6;

    /** \brief Name of a stage, for reports. */
    std::string
    toString (TensorVerificationStage stage);

    /** \brief What local verification found for one hypothesis. */
    struct TensorVerificationResult
    {
      TensorVerificationStage stage = TensorVerificationStage::COARSE_DIMENSIONS;
      /** The hypothesis refined by ICP (the hypothesis itself when ICP was not reached). */
      Eigen::Matrix4f transform = Eigen::Matrix4f::Identity ();
      /** max(D'_ms - D), the excess of the coarsely registered reduced meshes (Eq. 9). */
      double coarse_dimension_excess = 0.0;
      /** Correspondences within coarse_distance (default 6 d_res) before ICP, estimated from the sample, and n_c. */
      double coarse_correspondences = 0.0;
      double required_correspondences = 0.0;
      /** Correspondences within d_res after ICP, over every point (of both views with count_both_views). */
      double fine_correspondences = 0.0;
      /** max(D_ms - D) after ICP, in d_res. */
      double fine_dimension_excess = 0.0;
      /** ICP's RMS point-to-plane distance over its pairs, in the units of the points. */
      double icp_fitness = 0.0;
      /** The larger, over both directions, fraction of a view's points that the other view saw
        * and that lie in front of its surface (FREE_SPACE): exact up to kFreeSpaceMeasuredFactor times
        * free_space_fraction, above it only known to exceed that. */
      double free_space_violation = 0.0;
      /** FINE_OVERLAP without the fine count: the ICP stage check (CorrespondenceRejectorTensorVerification::
        * setIcpStageCheck()) found the pose where a hypothesis that failed that count had been. */
      bool icp_abandoned = false;
      /** ICP's pose at the end of each of its stages that ran (empty when ICP was not reached). */
      std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>> icp_stage_transforms;

      bool passed () const { return stage == TensorVerificationStage::PASSED; }
    };
  }
}
