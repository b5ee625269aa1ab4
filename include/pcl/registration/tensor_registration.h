/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/object_dimensions.h>
#include <pcl/features/tensor_descriptor.h>
#include <pcl/registration/correspondence_estimation_tensor.h>
#include <pcl/registration/correspondence_rejection_tensor_verification.h>
#include <pcl/registration/registration.h>
#include <pcl/registration/tensor_match.h>
#include <pcl/registration/tensor_verification.h>
#include <pcl/surface/scan_preparation.h>

#include <array>
#include <functional>

namespace pcl
{
  namespace registration
  {
    /** \brief Mesh preparation defaults for registration: Section 2's, at 1000 faces, reduced from
      * every second row and column of the range image (bun000-bun045: preparation 86 -> 62 ms; every
      * real pair of eval_paper --overlap registers as from M_i, the dragon one more at >= 0.5). */
    inline ScanPreparationParams
    registrationPreparation ()
    {
      ScanPreparationParams p;
      p.target_faces = 1000;
      p.reduction_grid_step = 2;
      return p;
    }

    /** \brief Every parameter of the pairwise pipeline, with the paper's values as defaults.
      * \ingroup registration
      */
    struct TensorRegistrationParams
    {
      /** Range image -> M_i -> M'_i (Section 2), reduced to 1000 faces rather than the paper's 400:
        * at 400 faces only 6% of the reduced vertices of bun000 recur within 2 d_res in bun045, and
        * no correct tensor match survived t_r and t_c; at 1000 faces 20% recur and 36 do. */
      ScanPreparationParams preparation = registrationPreparation ();
      /** Tensor grid N x N x N (Section 2: 10). */
      int grid_size = 10;
      /** Closest valid partners per vertex (Section 2: 3). */
      int partners_per_vertex = 3;
      /** Minimum mutual angle theta_d of a pair's normals, degrees (Section 2: 5). */
      double min_normal_angle = 5.0;
      /** Region growing over faces (the paper's method) rather than testing every face (default
        * false): brute force is exact, and with 1000 faces per view it computes bun000's and bun045's
        * tensors in about half the time (bench_tensor, BM_TensorsBunny at 400 faces: 1.5 times faster). */
      bool region_growing = false;
      /** t_r, minimum overlap ratio R_O (Eq. 5; Section 4: 0.5). */
      float overlap_threshold = 0.5f;
      /** t_c, minimum correlation C_c (Eq. 6; Section 4: 0.5). */
      float correlation_threshold = 0.5f;
      /** Delta theta_d of the index table, degrees (Section 2: 5). */
      double theta_bin_width = 5.0;
      /** The order in which matches are verified. */
      TensorMatchOrder order = TensorMatchOrder::BEST_FIRST;
      /** TensorRegistration computes the scene's tensors in this many batches (every k-th vertex
        * pair, TensorEstimation::setPairBatch), matching each and verifying its best matches before
        * computing the next: Fig. 7 computes the scene's tensors one at a time and stops at the
        * first verified match.
        * 1: all of them at once, then every match best first. 8 (default) halve the tensor and
        * matching time of bun000-bun045 with the same outcome on every real pair. On a symmetric
        * object a batch's best match can be the turned pose, which verification cannot tell from the
        * true one (the surfaces coincide); the ambiguity check (ambiguity_checks) refuses such pairs. */
      int scene_tensor_batches = 8;
      /** Matches of each batch verified before the next batch is computed (0: all of them). Those
        * left over from every batch are verified together once all are computed, in order, so that a
        * pair that needs many hypotheses meets them in nearly the order of a single batch. */
      int batch_hypotheses = 10;
      /** Local verification (Section 4.1). */
      TensorVerificationParams verification;
      /** Hypotheses verified at most before giving up (0: all matches). Section 7.3 finds most
        * correct matches among the first 50 scene tensors; on the real bunny pairs the last success
        * came at hypothesis 120. The cap bounds the time spent on views that do not overlap. */
      int max_hypotheses = 300;
      /** A hypothesis within this rotation (degrees) and translation (d_res) of one that ICP already
        * refuted is skipped: ICP would take it to the same wrong minimum. 0 disables. */
      double repeat_rotation = 3.0;
      double repeat_translation = 3.0;
      /** Beyond the paper: once a hypothesis passes, up to this many of the next hypotheses whose
        * pose is far from it (ambiguity_rotation, or the scene's centroid put mean(D)/2 away) are
        * verified too. If one of them also passes at a pose other than the first (beyond the repeat
        * tolerances), the surfaces fit in two ways (a symmetric object: every pose of a bumpless
        * ellipsoid passes together with its 180-degree turn) and the pair is reported ambiguous, not
        * registered, instead of whichever pose came first. 0 disables the check. */
      int ambiguity_checks = 2;
      /** Hypotheses within this rotation (degrees) of the passed pose, putting the scene's centroid
        * within mean(D)/2 of where it does, are taken as leading to it and not checked: from 25-50
        * degrees off, ICP takes bun045's hypotheses to the pose of bun000-bun045 that passed, at 20 ms
        * each. A symmetry finer than this (a sixfold one, a cylinder's) is not detected. */
      double ambiguity_rotation = 60.0;
    };

    /** \brief What one pairwise registration did: one object for apps, JSON and the bench. */
    struct TensorRegistrationReport
    {
      bool registered = false;
      /** Takes scene (source) points into the model's (target) frame; identity when not registered. */
      Eigen::Matrix4f transform = Eigen::Matrix4f::Identity ();
      std::size_t model_tensors = 0, scene_tensors = 0;
      std::size_t matches = 0;           ///< tensor pairs above t_r and t_c
      std::size_t comparisons = 0;       ///< tensor pairs compared (mu, Eq. 13)
      std::size_t hypotheses_tried = 0;  ///< matches verified until one passed (or all failed)
      std::size_t hypotheses_skipped = 0;  ///< repeats of hypotheses that ICP refuted
      /** Hypotheses that passed local verification but that the caller's HypothesisAcceptor refused
        * (global verification, Section 4.2). */
      std::size_t hypotheses_refused = 0;
      /** Hypotheses verified after one passed, looking for a second pose (ambiguity_checks). */
      std::size_t ambiguity_checks = 0;
      /** Two distinct poses passed verification: not registered (rival_transform is the second). */
      bool ambiguous = false;
      Eigen::Matrix4f rival_transform = Eigen::Matrix4f::Identity ();
      /** How many hypotheses failed at each stage (index: TensorVerificationStage). */
      std::array<std::size_t, kTensorVerificationStages> failures{};
      TensorMatch winning_match;                ///< valid when registered
      TensorVerificationResult verification;    ///< of the winning hypothesis when registered
      double resolution = 0.0;                  ///< d_res used by verification
      ObjectDimensions dimensions;              ///< D used by verification
      struct Timings
      {
        double prepare_ms = 0.0, tensors_ms = 0.0, matching_ms = 0.0, verification_ms = 0.0, total_ms = 0.0;
      } timings;
    };

    /** \brief Check every parameter of \a params before any work is done: the components' own
      * setters' ranges, a non-negative hypothesis cap and repeat tolerances.
      * \throw pcl::BadArgumentException naming the first value out of range
      */
    void
    checkParams (const TensorRegistrationParams& params);

    /** \brief The tensors of one prepared view (Section 2), with Eq. 2 and Eq. 3 taken from \a dims;
      * with \a batches > 1, only batch \a batch of its vertex pairs (TensorEstimation::setPairBatch).
      * \throw pcl::BadArgumentException or pcl::InvalidScanException on unusable input
      */
    pcl::PointCloud<pcl::TensorDescriptor>::Ptr
    computeViewTensors (const PreparedScan& scan, const ObjectDimensions& dims, const TensorRegistrationParams& params,
                        int batches = 1, int batch = 0);

    /** \brief Set the matcher's thresholds, index and order from \a params. */
    void
    configureMatcher (CorrespondenceEstimationTensor& matcher, const TensorRegistrationParams& params);

    /** \brief Give the verifier both views, D and the verification thresholds of \a params. */
    void
    configureVerifier (CorrespondenceRejectorTensorVerification& verifier,
                       const shared_ptr<const PreparedScan>& model, const pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr& model_tensors,
                       const shared_ptr<const PreparedScan>& scene, const pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr& scene_tensors,
                       const ObjectDimensions& dims, const TensorRegistrationParams& params);

    /** \brief The hypothesis of one match (Eq. 7-8), with the scene tensor in the order that matched. */
    Eigen::Matrix4f
    hypothesisOf (const TensorMatch& match, const pcl::PointCloud<pcl::TensorDescriptor>& model_tensors,
                  const pcl::PointCloud<pcl::TensorDescriptor>& scene_tensors);

    /** \brief A further test of a hypothesis that passed local verification, e.g. global verification
      * (Section 4.2; Fig. 7, steps 15-16): return false to refuse it, and the next tensor match is tried.
      * \param[in] result the locally verified hypothesis (result.transform: scene -> model, refined)
      */
    using HypothesisAcceptor = std::function<bool (const TensorVerificationResult& result)>;

    /** \brief Register a prepared scene view to a prepared model view with given tensors: match
      * (Section 4), then verify hypotheses in order until one passes (Section 4.1) and, when
      * \a accept is given, is accepted by it too.
      * \param[in,out] report filled in; its timings for preparation and tensors are left as they are
      * \param[in] accept optional further test of each locally verified hypothesis
      */
    void
    registerTensorViews (const shared_ptr<const PreparedScan>& model, const pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr& model_tensors,
                         const shared_ptr<const PreparedScan>& scene, const pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr& scene_tensors,
                         const ObjectDimensions& dims, const TensorRegistrationParams& params, TensorRegistrationReport& report,
                         const HypothesisAcceptor& accept = {});

    /** \brief registerTensorViews(), with the scene's tensors computed in
      * \a params.scene_tensor_batches batches: each batch is matched and its matches verified before
      * the next is computed, and the search stops at the first hypothesis that passes (Fig. 7).
      * \param[in,out] report filled in; the scene batches' time is added to its tensors time, and
      *            scene_tensors counts the tensors computed
      */
    void
    registerTensorViewsInBatches (const shared_ptr<const PreparedScan>& model, const pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr& model_tensors,
                                  const shared_ptr<const PreparedScan>& scene, const ObjectDimensions& dims,
                                  const TensorRegistrationParams& params, TensorRegistrationReport& report,
                                  const HypothesisAcceptor& accept = {});

    /** \brief Automatic pairwise registration of range images with tensors (Mian, Bennamoun & Owens,
      * IJCV 2006), used like pcl::SampleConsensusPrerejective: set the scene as source and the model as
      * target, call align(). It meshes and reduces both range images, computes their tensors,
      * matches them, and verifies one hypothesis at a time until one passes local verification.
      * hasConverged() is false when none does: the views are then reported as not registered, never
      * with an unverified transform.
      * \ingroup registration
      */
    class TensorRegistration : public Registration<pcl::PointXYZ, pcl::PointXYZ, float>
    {
      public:
        using Ptr = shared_ptr<TensorRegistration>;
        using ConstPtr = shared_ptr<const TensorRegistration>;

        TensorRegistration ()
        {
          reg_name_ = "TensorRegistration";
          // The method searches structures of its own: the base class's kd-tree of the target would
          // take 3 ms per align() of a 40,000-point scan and serve nothing.
          force_no_recompute_ = true;
        }

        /** \brief Set every parameter at once.
          * \throw pcl::BadArgumentException when one is out of range (see checkParams()) */
        void setParams (const TensorRegistrationParams& params)
        {
          checkParams (params);
          params_ = params;
        }
        const TensorRegistrationParams& getParams () const { return params_; }

        /** \brief Sensors of the scene (source) and model (target); default: +z (ScanViewpoint::fromPositiveZ). */
        void setSourceViewpoint (const ScanViewpoint& v) { source_viewpoint_ = v; }
        void setTargetViewpoint (const ScanViewpoint& v) { target_viewpoint_ = v; }

        /** \brief The object's dimensions D, from all its views (Eq. 1). Without it, D comes from the
          * two views alone, which underestimates the object when the views cover little of it.
          */
        void setObjectDimensions (const ObjectDimensions& dims) { dims_ = dims; has_dims_ = true; }

        /** \brief align(), but unusable input throws instead of being logged by PCL's Registration:
          * pcl::BadArgumentException when a cloud is missing, pcl::InvalidScanException when one has
          * fewer than three finite points. Either way no transform is reported.
          */
        void alignOrThrow (PointCloudSource& output);

        /** \brief What the last align() did. */
        const TensorRegistrationReport& getReport () const { return report_; }

      protected:
        void computeTransformation (PointCloudSource& output, const Matrix4& guess) override;

      private:
        TensorRegistrationParams params_;
        ScanViewpoint source_viewpoint_ = ScanViewpoint::fromPositiveZ ();
        ScanViewpoint target_viewpoint_ = ScanViewpoint::fromPositiveZ ();
        ObjectDimensions dims_;
        bool has_dims_{false};
        TensorRegistrationReport report_;
    };
  }
}
