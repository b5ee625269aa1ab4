/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/object_dimensions.h>
#include <pcl/common/view_extents.h>
#include <pcl/features/tensor_descriptor.h>
#include <pcl/registration/correspondence_rejection.h>
#include <pcl/registration/tensor_match.h>
#include <pcl/registration/point_to_plane_icp.h>
#include <pcl/registration/pose_conditioning.h>
#include <pcl/registration/tensor_verification.h>
#include <pcl/search/bounded_nearest_search.h>
#include <pcl/surface/range_view_projection.h>
#include <pcl/surface/range_view_projection_memo.h>
#include <pcl/surface/scan_preparation.h>

#include <memory>
#include <functional>
#include <limits>
#include <vector>

namespace pcl
{
  namespace registration
  {
    /** \brief Local verification of tensor matches (Section 4.1; Fig. 7, steps 4 to 14).
      *
      * Each correspondence (scene tensor -> model tensor) gives one rigid hypothesis (Eq. 7-8). It
      * survives only if, in turn: the registered reduced meshes exceed the object's dimensions D by
      * at most t_D (Eq. 9); at least n_c = min(|M_m|, |M_s|)/5 (the paper's 1/4:
      * doc/design.md#correspondence-count) scene points lie within
      * TensorVerificationParams::coarse_distance of the model (default 6 d_res, the paper's 2:
      * doc/design.md#coarse-correspondence-distance; with count_both_views, n_c/2 of each view); after
      * point-to-plane ICP, at least 2 n_c lie within d_res (n_c of each view); the registered fine
      * meshes exceed D by at most 2 d_res; and, beyond the paper, neither view puts surface where the
      * other's sensor saw through (doc/design.md#free-space-check). verify() runs the test on one
      * hypothesis and reports where it failed; getRemainingCorrespondences() keeps the correspondences
      * that pass.
      *
      * The point hooks of CorrespondenceRejector (requiresSourcePoints() ...) are not used: the test
      * needs the meshes and tensors of both views, which setModel()/setScene() provide.
      * \ingroup registration
      */
    class CorrespondenceRejectorTensorVerification : public CorrespondenceRejector
    {
      public:
        using Ptr = shared_ptr<CorrespondenceRejectorTensorVerification>;
        using ConstPtr = shared_ptr<const CorrespondenceRejectorTensorVerification>;
        using TensorCloudConstPtr = pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr;

        CorrespondenceRejectorTensorVerification () { rejection_name_ = "CorrespondenceRejectorTensorVerification"; }

        /** \brief The model view (target): its fine and reduced meshes, and its tensors; \a projections,
          * when given, keeps the view's z-buffers for every pair it is in (else this pair builds its own). */
        void setModel (const shared_ptr<const PreparedScan>& scan, const TensorCloudConstPtr& tensors,
                       const RangeViewProjectionMemo::Ptr& projections = nullptr);
        /** \brief The scene view (source): its fine and reduced meshes, and its tensors; \a projections
          * as for setModel(). */
        void setScene (const shared_ptr<const PreparedScan>& scan, const TensorCloudConstPtr& tensors,
                       const RangeViewProjectionMemo::Ptr& projections = nullptr);
        /** \brief Replace only the scene's tensors (e.g. the next batch, TensorEstimation::setPairBatch):
          * the search structures built for the scene's meshes are kept. */
        void setSceneTensors (const TensorCloudConstPtr& tensors) { scene_tensors_ = tensors; }

        /** \brief The matcher's details of the correspondences to verify next, index for index
          * (CorrespondenceEstimationTensor::getMatches()): each is then verified in the pair order it
          * matched in. Without them (empty, the default) a scene tensor whose pair order is ambiguous
          * is tried in both orders. */
        void setInputMatches (const std::vector<TensorMatch>& matches) { input_matches_ = matches; }

        /** \brief The object's dimensions D (Eq. 1), from all its views when known. */
        void setObjectDimensions (const ObjectDimensions& dims) { dims_ = dims; }
        const ObjectDimensions& getObjectDimensions () const { return dims_; }

        /** \brief Thresholds, ICP and sampling; a new sample size re-draws the scene sample.
          * \throw pcl::BadArgumentException when a value is out of range: n_c's fraction must be in
          * (0, 1] and the distances positive, else any pose (even a wrong one) could pass verification */
        void setParams (const TensorVerificationParams& params);
        const TensorVerificationParams& getParams () const { return params_; }

        /** \brief Called with the stage and pose each time a stage of verify()'s ICP ends, but the last:
          * false abandons the hypothesis there, as failing FINE_OVERLAP (TensorVerificationResult::
          * icp_abandoned). A search that keeps the stage poses of its hypotheses that failed the fine
          * count (TensorVerificationResult::icp_stage_transforms) spares the later stages of one that
          * reaches such a pose, as it would fail that count the same way. refine() does not call it.
          * Empty (default): every ICP runs to its end. */
        void
        setIcpStageCheck (std::function<bool (std::size_t stage, const Eigen::Matrix4f& pose)> check)
        {
          icp_stage_check_ = std::move (check);
        }

        /** \brief Stop after this many correspondences have passed (0: verify them all; default 0). */
        void setMaxAccepted (std::size_t n) { max_accepted_ = n; }
        std::size_t getMaxAccepted () const { return max_accepted_; }

        /** \brief d_res used for the distances: the mean of the two fine meshes' resolutions. */
        double getResolution () const;

        /** \brief Verify one hypothesis that takes scene points into the model's frame.
          * \param[in] hypothesis the rigid transform of a tensor match (transformFromTensorPair)
          * \param[out] result the stage reached and the measurements made
          * \param[in] run_icp refine the hypothesis by ICP (step 10) before the fine checks (default);
          *            false judges it as it is, e.g. a pose refine() has already refined
          * \param[in] dimension_factor the dimension checks' tolerances over D (Eq. 9, steps 4-6 and 13-14)
          *            times this (default 1; more for a rival, as the D of two views of a round object is short)
          * \return result.passed ()
          * \throw pcl::BadArgumentException when the model or the scene is missing, or \a dimension_factor is
          *        not positive and finite
          */
        bool verify (const Eigen::Matrix4f& hypothesis, TensorVerificationResult& result, bool run_icp = true,
                     double dimension_factor = 1.0);

        /** \brief \a hypothesis refined by verify()'s ICP alone, without any check: where verify() would
          * judge it (ICP ends early, as there, where too few pairs are left for the pose to pass). Lets a
          * caller skip the checks of a hypothesis that converges to a pose it knows.
          * \throw pcl::BadArgumentException when the model or the scene is missing
          */
        Eigen::Matrix4f refine (const Eigen::Matrix4f& hypothesis);

        /** \brief How well the surface the views share under \a t pins the pose down: the conditioning of
          * the scene's sample (sample_points) paired with the model's fine points within 2 fine_distance d_res.
          * \throw pcl::BadArgumentException when the model or the scene is missing
          */
        PoseConditioning poseConditioning (const Eigen::Matrix4f& t);

        /** \brief What each view shows of the other under \a t, where the other's sensor could see it
          * (TensorCovisibility).
          * \throw pcl::BadArgumentException when the model or the scene is missing
          */
        TensorCovisibility covisibility (const Eigen::Matrix4f& t);

        /** \brief The FREE_SPACE stage's margin: free_space_distance d_res, or three times the two views'
          * combined noise (PreparedScan::noise) when larger. Needs the model and the scene. */
        double getFreeSpaceMargin () const;

        /** \brief The larger, over both directions, fraction of the points of one view that the other's
          * sensor saw and that lie more than \a margin in front of its surface, under \a t (the FREE_SPACE
          * stage's measure, TensorVerificationResult::free_space_violation, at any margin).
          * \throw pcl::BadArgumentException when the model or the scene is missing
          */
        double freeSpaceViolation (const Eigen::Matrix4f& t, double margin);

        /** \brief freeSpaceViolation() at getFreeSpaceMargin(), where a point on a line of sight that
          * passes farther than \a empty_margin d_res from all of the other view's surface violates it
          * too (it lies where that sensor saw background; RangeViewProjection::markEmptySpace()),
          * whatever TensorVerificationParams::empty_space_margin is. The z-buffers are built once per
          * margin and pair (and per view with a memo).
          * \throw pcl::BadArgumentException when the model or the scene is missing or \a empty_margin is not positive
          */
        double emptySpaceViolation (const Eigen::Matrix4f& t, double empty_margin);

        /** \brief Keep the correspondences whose hypothesis passes verify(), in order.
          * The transform of each is available from getAcceptedTransforms(), index for index.
          */
        void
        getRemainingCorrespondences (const pcl::Correspondences& original_correspondences,
                                     pcl::Correspondences& remaining_correspondences) override;

        /** \brief Refined transforms of the correspondences kept by the last getRemainingCorrespondences(). */
        const std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>>&
        getAcceptedTransforms () const { return accepted_transforms_; }

        /** \brief What verify() found for each correspondence the last getRemainingCorrespondences()
          * examined, in order (it stops early with setMaxAccepted()): the stage each failed at. */
        const std::vector<TensorVerificationResult>&
        getResults () const { return results_; }

      protected:
        void
        applyRejection (pcl::Correspondences& correspondences) override
        {
          getRemainingCorrespondences (*input_correspondences_, correspondences);
        }

      private:
        using PointCloudN = pcl::PointCloud<pcl::PointNormal>;

        /** Build both views' searches and samples (the scene's is ICP's input), once per input. */
        void prepare ();
        /** Points of \a cloud, under \a t, with a point of \a search's cloud within \a radius. */
        static std::size_t countCorrespondences (const PointCloudN& cloud, const Eigen::Matrix4f& t,
                                                 const pcl::BoundedNearestSearch& search, double radius);
        /** Correspondences within \a radius under \a t, counted on \a scene_points (and with
          * count_both_views on \a model_points: twice the smaller count), scaled from those points
          * (the samples or the whole views) to the whole views. */
        double correspondences (const PointCloudN& scene_points, const PointCloudN& model_points,
                                const Eigen::Matrix4f& t, double radius) const;
        /** Points of the scene's sample that must have a correspondence for correspondences() on the
          * samples to reach \a correspondences. */
        double scenePairsNeeded (double correspondences) const;
        /** n_c: correspondence_fraction of the smaller view's points (Section 4.1, step 7). */
        double requiredCorrespondences () const;
        /** The pairs below which verify()'s ICP ends: fewer than the sampled fine count needs, even at a
          * coarse stage's wider distance, and the pose would fail that count. */
        std::size_t icpMinPairs () const;
        /** verify()'s ICP from \a hypothesis on the scene's sample; stages before the last end with
          * fewer than \a min_pairs pairs (PointToPlaneIcpParams::min_pairs), and with \a check_stages
          * when the stage check says so. */
        PointToPlaneIcpResult icp (const Eigen::Matrix4f& hypothesis, std::size_t min_pairs, bool check_stages = false) const;
        /** The z-buffer of \a view, from \a memo when it has one; background farther than \a empty_margin
          * d_res from the surface is marked empty when \a empty_margin is positive. */
        RangeViewProjectionMemo::Projection projectView (const shared_ptr<const PreparedScan>& view,
                                                         const RangeViewProjectionMemo::Ptr& memo, double empty_margin) const;
        /** The z-buffers of both views, built once per pair, for the first hypothesis that needs them. */
        void projectViews ();
        /** The larger fraction, over both directions, of one view's points that violate the other's
          * free space in its z-buffer (\a model_view or \a scene_view) under \a t; once it is known to
          * exceed \a stop_above, that lower bound. */
        double violation (const Eigen::Matrix4f& t, double margin, const RangeViewProjection& model_view,
                          const RangeViewProjection& scene_view,
                          double stop_above = std::numeric_limits<double>::infinity ()) const;
        /** max(D_combined - D) of the model points and the transformed scene points, in the best of
          * their combined principal frame and each view's own (registeredDimensionExcess). */
        double dimensionExcess (const ViewExtents& model, const ViewExtents& scene, const Eigen::Matrix4f& t) const;

        shared_ptr<const PreparedScan> model_, scene_;
        TensorCloudConstPtr model_tensors_, scene_tensors_;
        ObjectDimensions dims_;
        TensorVerificationParams params_;
        std::size_t max_accepted_{0};
        bool prepared_{false};

        pcl::BoundedNearestSearch model_search_, scene_search_;
        ViewExtents model_fine_extents_, scene_fine_extents_, model_reduced_extents_, scene_reduced_extents_;
        RangeViewProjectionMemo::Ptr model_projections_, scene_projections_;
        RangeViewProjectionMemo::Projection model_view_, scene_view_;
        RangeViewProjectionMemo::Projection model_empty_view_, scene_empty_view_;  ///< emptySpaceViolation()'s
        double empty_views_margin_{0.0};  ///< the margin they were marked with; 0: none built
        PointCloudN::Ptr scene_sample_{new PointCloudN}, model_sample_{new PointCloudN};
        std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>> accepted_transforms_;
        std::vector<TensorMatch> input_matches_;
        std::vector<TensorVerificationResult> results_;
        std::function<bool (std::size_t, const Eigen::Matrix4f&)> icp_stage_check_;
    };
  }
}
