/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/registration/global_verification.h>
#include <pcl/registration/multiview_point_to_plane_icp.h>
#include <pcl/registration/tensor_registration.h>
#include <pcl/registration/view_pair_ranking.h>
#include <pcl/surface/scan_volumetric_integration.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace pcl
{
  namespace registration
  {
    /** \brief One range image to register with the others. */
    struct MultiviewInput
    {
      std::string name;
      /** Points in the view's own frame (organized or not; NaN allowed). */
      pcl::PointCloud<pcl::PointXYZ>::ConstPtr cloud;
      /** Where the sensor was (default: looking along +z, ScanViewpoint::fromPositiveZ()). */
      ScanViewpoint viewpoint = ScanViewpoint::fromPositiveZ ();
      /** The view prepared before (e.g. from a cache; prepareTensorView, centred or not), or null
        * (default): then \a cloud is meshed. Its tensors are used when they were computed with the D
        * of this registration. */
      TensorView::ConstPtr view;
      /** True when the view's pose is known, e.g. a view of a model being extended with new views:
        * the views with known poses are joined from the start, in the frame of their poses, and keep
        * their poses through the global step; only the others are registered, to them and to each
        * other. False (default): the view is registered. */
      bool pose_known = false;
      /** The known pose: the view's own frame -> the common frame (as ViewRegistrationStatus::pose). */
      Eigen::Affine3d known_pose = Eigen::Affine3d::Identity ();
    };

    /** \brief How multiview registration chooses the pairs it registers. */
    enum class ViewSearch
    {
      /** Beyond the paper: every pair of views ranked from their tensors (ViewPairRanking) and
        * registered best first while it joins two groups of registered views, with global
        * verification of the joined group. For views in any order; views that no chain of verified
        * pairs links form separate groups (components), each a model of its own. */
      RANKED,
      /** The paper's (Fig. 9): each view, in the order given, against the views registered before it. */
      ORDERED
    };

    /** \brief The stages of multiview registration, in order (Fig. 9, modules 1-5). */
    enum class MultiviewStage
    {
      PREPARATION,  ///< meshing and reduction of each view (M_i, M'_i)
      TENSORS,      ///< tensors of each view
      PAIRWISE,     ///< each view registered to the registered ones, with global verification
      GLOBAL        ///< simultaneous registration of all registered views
    };

    /** \brief Name of a stage, for progress bars and reports. */
    std::string
    toString (MultiviewStage stage);

    /** \brief A full pairwise registration of views \a scene into \a model's frame (indices into the
      * views), both prepared, without global verification: registerTensorViews() by default; an
      * application may answer from a cache or from results computed elsewhere. Called from several
      * threads at once. */
    using ViewPairRegistration = std::function<TensorRegistrationReport (
        int model, int scene, const TensorView::ConstPtr& model_view, const TensorView::ConstPtr& scene_view,
        const ObjectDimensions& dims, const TensorRegistrationParams& params)>;

    /** \brief The scores RANKED search may take as known (ViewPairScoreMemo) when its views' tensors were
      * computed with \a dims and are matched with \a params and \a ranking: an application may keep them
      * in a cache. Called once per registration, before the pairs are ranked. */
    using ViewPairScoreCache = std::function<ViewPairScoreMemo (
        const ObjectDimensions& dims, const TensorRegistrationParams& params, const ViewPairRankingParams& ranking)>;

    /** \brief Progress: \a done of \a total steps of \a stage are finished (views, or global iterations). */
    using MultiviewProgress = std::function<void (MultiviewStage stage, std::size_t done, std::size_t total)>;

    /** \brief Every parameter of multiview registration (Sections 4.2 and 5), with defaults. */
    struct MultiviewRegistrationParams
    {
      /** The pairwise pipeline (Sections 2-4.1). */
      TensorRegistrationParams pairwise;
      /** Global verification (Section 4.2): 4 d_res on the two largest extents. */
      GlobalVerificationParams global_verification;
      /** The object's dimensions D when they are known (any order; sorted when used). Zero (default):
        * from all views by Eq. 1, which underestimates an extent that no single view sees whole (the
        * dragon's depth on a turntable, by 28 d_res), and then the dimension checks need more tolerance. */
      Eigen::Vector3d object_dimensions = Eigen::Vector3d::Zero ();
      /** How pairs are chosen (default RANKED: any order). */
      ViewSearch search = ViewSearch::RANKED;
      /** RANKED: the sample of tensors that ranks the pairs. */
      ViewPairRankingParams ranking;
      /** RANKED: a view whose this many candidate pairs failed is left out of further pairs (0: no
        * limit), so that a view of another object costs a few refusals, not one per view. */
      int max_failed_pairs = 8;
      /** RANKED: hypotheses a pair may verify on the first pass over the candidates (0: as many as
        * the pairwise max_hypotheses). A pair refused within them is registered again, with every
        * hypothesis, only if views are still apart when the first pass is over: a true pair is
        * nearly always found by its first few hypotheses, and a refusal then costs a fraction. */
      int first_pass_hypotheses = 20;
      /** RANKED: on the second pass, pairs registered with every hypothesis between two groups of
        * views, best ranked first (0: all): a refusal there is slow, and if two groups overlap their
        * best-ranked pairs are the likeliest to show it. */
      int second_pass_pairs = 2;
      /** A turntable set: the last view also overlaps the first, and the global step closes the loop. */
      bool loop = false;
      /** ORDERED: registered views each new view is tried against, most recently registered first (0: all).
        * With explicit pairs only the view's registered partners are tried. */
      int max_references = 0;
      /** ORDERED: try every reference and keep the registration with the largest overlap, instead of the first
        * that passes verification: slower, for unordered sets whose neighbours are not known. */
      bool keep_best = false;
      /** Run the global step (Section 5, module 5 of Fig. 9). */
      bool global_registration = true;
      /** The global step: simultaneous point-to-plane ICP over the overlapping pairs. */
      MultiviewIcpParams global;
      /** Besides the pairs that registration used (and the loop), the global step uses every pair
        * of registered views that overlaps by at least this fraction under the pairwise poses (0: none). */
      double min_overlap = 0.3;
      /** ... of those, each view's this many most overlapping (0: all); a pair stays when it is among
        * either view's. The global step's cost grows with its pairs. */
      int max_overlap_pairs = 6;
    };

    /** \brief Check every parameter of \a params before any view is read: the pairwise ones
      * (checkParams(const TensorRegistrationParams&)), global verification, the global step and the
      * multiview settings, so that a bad value is refused before the pairwise work, not after it.
      * \throw pcl::BadArgumentException naming the first value out of range
      */
    void
    checkParams (const MultiviewRegistrationParams& params);

    /** \brief What happened to one view. */
    struct ViewRegistrationStatus
    {
      std::string name;
      bool registered = false;
      /** The view it was registered to (-1: its component's reference view, or not registered). */
      int reference = -1;
      /** Its group of views registered together, largest first (0: the main model; -1: not registered). */
      int component = -1;
      /** View -> its component's frame (the frame of the component's reference view): after the
        * global step when it ran. */
      Eigen::Affine3d pose = Eigen::Affine3d::Identity ();
      /** The same pose from pairwise registration alone, before the global step. */
      Eigen::Affine3d pairwise_pose = Eigen::Affine3d::Identity ();
      /** The pose was given (MultiviewInput::pose_known) and kept, not registered here. */
      bool pose_kept = false;
      /** The accepted pairwise registration (or the last one tried when none was accepted). */
      TensorRegistrationReport pairwise;
      /** References tried, and locally verified hypotheses refused by global verification over all of them. */
      std::size_t references_tried = 0;
      std::size_t globally_refused = 0;
      /** max(D_L - D) in d_res of the registered views with this one added (Section 4.2). */
      double global_excess = 0.0;
      /** Why the view could not be used at all (empty when it could). */
      std::string error;
      /** M_i and M'_i of the view (null when it could not be prepared), for integration. */
      std::shared_ptr<const PreparedScan> prepared;
      /** The view with its tensors (null when it could not be used), e.g. to keep in a cache. */
      TensorView::ConstPtr view;
      double prepare_ms = 0.0, tensors_ms = 0.0, pairwise_ms = 0.0;
    };

    /** \brief One pair RANKED search registered fully, in the order it did. */
    struct ViewPairAttempt
    {
      int first = -1, second = -1;  ///< the views (first < second; second registered into first's frame)
      double score = 0.0;           ///< its ranking score (ViewPairCandidate)
      bool registered = false;      ///< pairwise registration passed local verification
      bool joined = false;          ///< ... and global verification of the joined groups
      bool full = false;            ///< with every hypothesis (the second pass), not the first pass's few
      double excess = 0.0;          ///< max(D_L - D) in d_res of the joined groups (when registered)
      double ms = 0.0;              ///< wall time of the pairwise registration
    };

    /** \brief What multiview registration did: one object for apps, JSON and the bench. */
    struct MultiviewRegistrationResult
    {
      std::vector<ViewRegistrationStatus> views;
      ObjectDimensions dimensions;  ///< D from all usable views (Eq. 1)
      double resolution = 0.0;      ///< d_res: the mean of the usable views' fine resolutions
      int reference = -1;           ///< the view that defines the common frame (of component 0)
      int components = 0;           ///< groups of views registered together (one model each)
      ViewPairs pairs;              ///< the pairs the global step used
      /** The registrations that joined the views (RANKED: a spanning tree of each component). */
      ViewPairs joins;
      /** RANKED: every pair considered, best first, and the pairs fully registered, in order. */
      std::vector<ViewPairCandidate> candidates;
      /** RANKED: the candidates scored here, the others' scores being known (setPairScoreCache()). */
      std::size_t candidates_scored = 0;
      /** RANKED: pairs registered ahead of their turn on a core that was idle, and then not needed (a
        * join before their turn made them redundant). Their work is not in \a attempts. */
      std::size_t pairs_registered_ahead_unused = 0;
      std::vector<ViewPairAttempt> attempts;
      MultiviewIcpResult global;    ///< what the global step did (poses: also in views[i].pose)
      struct Timings
      {
        double prepare_ms = 0.0, tensors_ms = 0.0, ranking_ms = 0.0, pairwise_ms = 0.0, global_ms = 0.0, total_ms = 0.0;
      } timings;

      std::size_t registeredCount () const;
    };

    /** \brief The registered views of one component as volumetric integration takes them: each view's
      * fine mesh M_i in its own frame (sharing ownership of the view's prepared scan) and its pose
      * after the global step; without the views of kept poses when \a kept_poses is false (e.g. when
      * they are in a volume integrated before, ScanVolumetricIntegration::setInitialVolume()).
      * \ingroup registration
      */
    std::vector<pcl::IntegrationView>
    registeredIntegrationViews (const MultiviewRegistrationResult& result, int component = 0, bool kept_poses = true);

    /** \brief Automatic registration of ordered views (Mian et al., Sections 4.2 and 5; Fig. 9,
      * modules 1-5): every view is meshed and reduced and its tensors computed once, with D from all
      * views (Eq. 1). The first usable view defines the common frame; each further view, in order,
      * is registered pairwise (Sections 4-4.1) to registered views, most recent first, and a locally
      * verified registration is accepted only if all the views registered so far, with it, still fit
      * in D + 4 d_res (global verification, Section 4.2); otherwise the next tensor match is tried
      * (Fig. 7). A view that cannot be registered (another object, no overlap) is reported and left
      * out; views that failed are tried again once others have been registered. Finally a global
      * step moves all views together to spread the remaining error (Section 5; loop closure for
      * turntables).
      * \ingroup registration
      */
    class MultiviewTensorRegistration
    {
      public:
        using Ptr = shared_ptr<MultiviewTensorRegistration>;
        using ConstPtr = shared_ptr<const MultiviewTensorRegistration>;

        /** \brief Set every parameter at once.
          * \throw pcl::BadArgumentException when one is out of range (see checkParams()) */
        void setParams (const MultiviewRegistrationParams& params)
        {
          checkParams (params);
          params_ = params;
        }
        const MultiviewRegistrationParams& getParams () const { return params_; }

        /** \brief The overlapping pairs (indices into the views), when known (e.g. a pairs file);
          * empty (default): the views are ordered, each overlapping one registered before it. */
        void setPairs (const ViewPairs& pairs) { pairs_ = pairs; }
        const ViewPairs& getPairs () const { return pairs_; }

        /** \brief Called from the working threads, one call at a time. */
        void setProgressCallback (const MultiviewProgress& progress) { progress_ = progress; }

        /** \brief Threads for the views' meshes and tensors and for the references a view is tried
          * against (0, the default: every core). The result is the same for any number. */
        void setNumberOfThreads (unsigned threads) { threads_ = threads; }
        unsigned getNumberOfThreads () const { return threads_; }

        /** \brief How RANKED search registers a pair (default: registerTensorViews() with the pairwise
          * parameters). */
        void setPairRegistration (const ViewPairRegistration& registration) { pair_registration_ = registration; }

        /** \brief Where RANKED search finds the scores of pairs ranked before (default: none; every pair
          * is scored). */
        void setPairScoreCache (const ViewPairScoreCache& scores) { pair_scores_ = scores; }

        /** \brief Register the views.
          * \throw pcl::BadArgumentException on a pair out of range or bad parameters; a view that
          * cannot be used (too few points) is reported in its status, not thrown
          */
        MultiviewRegistrationResult compute (const std::vector<MultiviewInput>& views) const;

      private:
        MultiviewRegistrationParams params_;
        ViewPairs pairs_;
        MultiviewProgress progress_;
        unsigned threads_{0};
        ViewPairRegistration pair_registration_;
        ViewPairScoreCache pair_scores_;
    };
  }
}
