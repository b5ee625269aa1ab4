/*
 * pcl_tensor: the hypothesis search of pairwise registration (private to the library): tensor
 * matching and verification through the PCL correspondence estimator and rejector, the scene's
 * tensors batch by batch (Fig. 7), refuted repeats skipped, the ambiguity check, and a second round of
 * the matches under t_r or t_c when the first settles nothing.
 */
#include "tensor_hypothesis_search.h"
#include "tensor_configuration.h"

#include <pcl/common/time.h>
#include <pcl/registration/tensor_match.h>

#include <algorithm>
#include <cmath>

namespace pcl
{
  namespace registration
  {
    namespace detail
    {
      namespace
      {
        using TensorCloud = pcl::PointCloud<pcl::TensorDescriptor>;

        /** cos(angle / 2) of the rotation from \a b to \a a, from the trace, without acos. */
        double
        cosHalfAngleBetween (const Eigen::Matrix4f& a, const Eigen::Matrix4f& b)
        {
          const Eigen::Matrix3f d = a.topLeftCorner<3, 3> () * b.topLeftCorner<3, 3> ().transpose ();
          return 0.5 * std::sqrt (std::max (0.0, 1.0 + static_cast<double> (d.trace ())));
        }

        /** Two poses within \a degrees of each other that put \a point within \a distance of the same place. */
        bool
        posesAgree (const Eigen::Matrix4f& a, const Eigen::Matrix4f& b, const Eigen::Vector4f& point, double degrees, double distance)
        {
          return cosHalfAngleBetween (a, b) >= std::cos (degrees * M_PI / 360.0) &&
                 static_cast<double> (((a - b) * point).norm ()) <= distance;
        }

        /** A probed rival pose is another answer when it is this far from the kept one (degrees, and
          * d_res at the scene's centroid): nearer, it is the same pose where ICP stopped. */
        constexpr double kRivalRotation = 5.0;
        constexpr double kRivalTranslation = 10.0;

        /** The probes: steps of 0.35 and 0.8 along the two least constrained motions (rivalPoses()), and
          * turns of 90, 135 and 180 degrees along the least constrained one's screw (screwTurnPoses()).
          * The steps turn a pose by 46 degrees at most, yet a teapot's body also fits a quarter turn
          * away (doc/design.md#rival-probe). */
        const std::vector<double> kRivalSteps{0.35, 0.8};
        const std::vector<double> kRivalTurns{0.5 * M_PI, 0.75 * M_PI, M_PI};
        /** The valley probes (probeValley()) go this many times as far as another answer is, and doubt
          * the answer only when they keep this share of its fine correspondences (doc/design.md#rival-probe). */
        constexpr double kValleyMargin = 1.5;
        constexpr double kValleyFit = 0.95;

        /** A rival needs less evidence than an answer: one that fails only the free-space check, by at
          * most this many times free_space_fraction, still makes the pair ambiguous. The stricter the
          * check, the fewer rivals pass it; doubting on weaker evidence keeps a strict check from turning
          * ambiguous pairs into wrong answers (doc/design.md#free-space-check). verify() measures the
          * violation exactly up to here. */
        constexpr double kRivalFreeSpaceFactor = kFreeSpaceMeasuredFactor;

        /** A rival is dismissed on empty-space evidence only when the kept pose shows at most this
          * fraction of the rival's (TensorRegistrationParams::rival_empty_space_margin): one-sided
          * evidence, not a view whose background is cropped or missed, which speaks against both. */
        constexpr double kKeptEmptySpaceRatio = 0.05;

        /** Hypotheses that reached ICP and failed; a close repeat would fail the same way. */
        class RefutedHypotheses
        {
          public:
            RefutedHypotheses (double degrees, double distance) : cos_half_ (std::cos (degrees * M_PI / 360.0)), distance_ (distance) {}

            bool
            contains (const Eigen::Matrix4f& t) const
            {
              for (const auto& r : refuted_)
                if (cosHalfAngleBetween (t, r) >= cos_half_ && (t.topRightCorner<3, 1> () - r.topRightCorner<3, 1> ()).norm () <= distance_)
                  return true;
              return false;
            }

            void add (const Eigen::Matrix4f& t) { refuted_.push_back (t); }

          private:
            double cos_half_, distance_;
            std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>> refuted_;
        };

        /** The report of a registration about to start: nothing tried, nothing found. */
        void
        resetReport (TensorRegistrationReport& report, std::size_t model_tensors, const ObjectDimensions& dims)
        {
          report.model_tensors = model_tensors;
          report.scene_tensors = 0;
          report.matches = 0;
          report.comparisons = 0;
          report.registered = false;
          report.transform = Eigen::Matrix4f::Identity ();
          report.failures.fill (0);
          report.hypotheses_tried = 0;
          report.hypotheses_skipped = 0;
          report.hypotheses_refused = 0;
          report.ambiguity_checks = 0;
          report.ambiguous = false;
          report.guess_accepted = false;
          report.rival_transform = Eigen::Matrix4f::Identity ();
          report.dimensions = dims;
          report.timings.matching_ms = 0.0;
          report.timings.verification_ms = 0.0;
        }

        Eigen::Vector4f
        centroidOf (const pcl::PointCloud<pcl::PointNormal>& cloud)
        {
          Eigen::Vector4d sum = Eigen::Vector4d::Zero ();
          for (const auto& p : cloud)
            sum.head<3> () += p.getVector3fMap ().cast<double> ();
          sum /= static_cast<double> (std::max<std::size_t> (1, cloud.size ()));
          sum.w () = 1.0;
          return sum.cast<float> ();
        }

        /** Matching and verification of one view pair, batch after batch of scene tensors: the refuted
          * hypotheses, the hypothesis count and the verifier's search structures carry over. */
        class HypothesisSearch
        {
          public:
            HypothesisSearch (const TensorView& model, const TensorCloud::ConstPtr& model_tensors, const TensorView& scene,
                              const TensorCloud::ConstPtr& scene_tensors, const ObjectDimensions& dims,
                              const TensorRegistrationParams& params, TensorRegistrationReport& report, const HypothesisAcceptor& accept)
              : model_tensors_ (model_tensors), params_ (params), report_ (report), accept_ (accept),
                scene_centroid_ (centroidOf (*scene.scan->fine.cloud)),
                far_distance_ (0.5 * dims.mean ())
            {
              TensorView model_with_tensors (model);
              model_with_tensors.tensors = model_tensors;
              configureVerifier (verification_, model_with_tensors, scene_tensors, scene, dims, params);
              report.resolution = verification_.getResolution ();
              refuted_ = RefutedHypotheses (params.repeat_rotation, params.repeat_translation * report.resolution);
              refuted_answers_ = refuted_;
              verification_.setIcpStageCheck ([this] (std::size_t stage, const Eigen::Matrix4f& pose) {
                return stage >= icp_dead_ends_.size () || !icp_dead_ends_[stage].contains (pose);
              });
            }

            // The verifier's ICP stage check points at this search's dead ends.
            HypothesisSearch (const HypothesisSearch&) = delete;
            HypothesisSearch& operator= (const HypothesisSearch&) = delete;

            /** The caller's guess, verified before any tensor match: taken when it passes. */
            bool
            tryGuess (const Eigen::Matrix4f& guess)
            {
              pcl::StopWatch watch;
              ++report_.hypotheses_tried;
              TensorVerificationResult result;
              const bool passed = verification_.verify (guess, result) && (!accept_ || accept_ (result));
              if (passed)
              {
                report_.registered = report_.guess_accepted = true;
                report_.verification = result;
                report_.transform = result.transform;
              }
              else if (result.stage != TensorVerificationStage::PASSED)
                ++report_.failures[static_cast<std::size_t> (result.stage)];
              report_.timings.verification_ms += watch.getTime ();
              return passed;
            }

            /** Match \a batch (scene tensors from index \a first on) and verify its first \a budget
              * matches in order (0: all); the others wait for finish().
              * \return true once registered or out of hypotheses: no later batch is needed */
            bool
            search (const TensorCloud::ConstPtr& batch, std::size_t first, std::size_t budget = 0)
            {
              pcl::StopWatch watch;
              CorrespondenceEstimationTensor estimation;
              configureMatcher (estimation, params_);
              // One pass at the second round's thresholds: its matches wait in below_thresholds_.
              estimation.setOverlapThreshold (secondOverlapThreshold ());
              estimation.setCorrelationThreshold (secondCorrelationThreshold ());
              estimation.setInputSource (batch);
              estimation.setInputTarget (model_tensors_);
              pcl::Correspondences correspondences;
              estimation.determineCorrespondences (correspondences);
              std::vector<TensorMatch> matches = estimation.getMatches ();
              const auto below = std::stable_partition (matches.begin (), matches.end (), [this] (const TensorMatch& m) {
                return passesThresholds (m, params_.overlap_threshold, params_.correlation_threshold);
              });
              keep (below, matches.end (), first, below_thresholds_);
              matches.erase (below, matches.end ());
              report_.matches += matches.size ();
              report_.comparisons += estimation.getComparisons ();
              report_.timings.matching_ms += watch.getTime ();
              watch.reset ();
              const std::size_t now = budget > 0 ? std::min (budget, matches.size ()) : matches.size ();
              // The deferred matches may still serve as rivals of a pose this batch verifies.
              const bool done = verify (matches, now, batch, first);
              if (!done)
                keep (matches.begin () + static_cast<std::ptrdiff_t> (now), matches.end (), first, deferred_);
              report_.timings.verification_ms += watch.getTime ();
              return done;
            }

            /** Verify the matches search() deferred, all batches' together in the matcher's order, on
              * \a scene_tensors, every batch's tensors in the order they were computed. */
            void
            finish (const TensorCloud::ConstPtr& scene_tensors)
            {
              pcl::StopWatch watch;
              sortTensorMatches (deferred_, params_.order);
              verify (deferred_, deferred_.size (), scene_tensors, 0);
              deferred_.clear ();
              report_.timings.verification_ms += watch.getTime ();
            }

            /** The second round (TensorRegistrationParams::fallback_overlap_threshold): when the first
              * found neither a pose nor a doubt and the cap is not reached, the matches search() found below
              * t_r or t_c, all batches' together in the matcher's order, on \a scene_tensors. */
            void
            searchBelowThresholds (const TensorCloud::ConstPtr& scene_tensors)
            {
              if (!report_.registered && !report_.ambiguous && !capReached ())
              {
                pcl::StopWatch watch;
                sortTensorMatches (below_thresholds_, params_.order);
                report_.matches += below_thresholds_.size ();
                verify (below_thresholds_, below_thresholds_.size (), scene_tensors, 0);
                report_.timings.verification_ms += watch.getTime ();
              }
              below_thresholds_.clear ();
            }

          private:
            /** t_r and t_c of the second round, never above the first's. */
            float secondOverlapThreshold () const { return std::min (params_.fallback_overlap_threshold, params_.overlap_threshold); }
            float secondCorrelationThreshold () const
            {
              return std::min (params_.fallback_correlation_threshold, params_.correlation_threshold);
            }

            /** Append [\a begin, \a end) to \a kept, their scene indices moved past the \a first tensors of earlier batches. */
            static void
            keep (std::vector<TensorMatch>::const_iterator begin, std::vector<TensorMatch>::const_iterator end, std::size_t first,
                  std::vector<TensorMatch>& kept)
            {
              for (auto m = begin; m != end; ++m)
              {
                kept.push_back (*m);
                kept.back ().scene += static_cast<int> (first);
              }
            }

            /** The poses at which the ICP of a hypothesis that then failed the fine count ended its stages:
              * a later ICP that ends a stage there would fail it the same way (the fine count does not
              * depend on the dimension factor, so this holds for rivals too). */
            void
            addDeadEnds (const std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>>& stage_poses)
            {
              for (std::size_t k = 0; k < stage_poses.size (); ++k)
              {
                if (icp_dead_ends_.size () <= k)
                  icp_dead_ends_.emplace_back (params_.repeat_rotation, params_.repeat_translation * report_.resolution);
                icp_dead_ends_[k].add (stage_poses[k]);
              }
            }

            bool
            capReached () const
            {
              return params_.max_hypotheses > 0 && report_.hypotheses_tried >= static_cast<std::size_t> (params_.max_hypotheses);
            }

            /** Local verification through the rejector's PCL interface, then the caller's acceptor;
              * refuted poses are remembered. */
            bool
            passes (const TensorMatch& match, const TensorCloud::ConstPtr& batch, const Eigen::Matrix4f& hypothesis,
                    TensorVerificationResult& result)
            {
              pcl::Correspondences one{pcl::Correspondence (match.scene, match.model, 1.0f - match.correlation)}, kept;
              verification_.setSceneTensors (batch);
              verification_.setInputMatches ({match});
              verification_.getRemainingCorrespondences (one, kept);
              result = verification_.getResults ().front ();
              if (kept.empty ())
              {
                if (result.stage == TensorVerificationStage::FINE_OVERLAP || result.stage == TensorVerificationStage::FINE_DIMENSIONS)
                  refuted_.add (hypothesis);
                if (result.stage == TensorVerificationStage::FINE_OVERLAP && !result.icp_abandoned)
                  addDeadEnds (result.icp_stage_transforms);
                if (result.stage == TensorVerificationStage::FREE_SPACE)
                  refuted_answers_.add (hypothesis);
                return false;
              }
              if (accept_ && !accept_ (result))
              {
                // Refused by the caller (global verification): a close repeat converges to the same pose.
                ++report_.hypotheses_refused;
                refuted_.add (hypothesis);
                return false;
              }
              return true;
            }

            /** Whether \a result, which failed verification or passed it, is evidence enough for a rival:
              * it passed, or it failed only at the free-space check within kRivalFreeSpaceFactor (unless
              * \a outright); and the caller's acceptor takes it. A pose refused by D alone is judged again
              * with rival_dimension_factor, ICP first unless it is \a refined already, and \a result holds
              * that judgement: excused D, it is excused nothing else. */
            bool
            rivalPasses (TensorVerificationResult& result, bool refined, bool outright)
            {
              const bool against_d = result.stage == TensorVerificationStage::COARSE_DIMENSIONS ||
                                     result.stage == TensorVerificationStage::FINE_DIMENSIONS;
              if (against_d && params_.rival_dimension_factor > 1.0)
              {
                verification_.verify (result.transform, result, !refined && result.stage == TensorVerificationStage::COARSE_DIMENSIONS,
                                      params_.rival_dimension_factor);
                outright = true;
              }
              const bool verified = result.passed () ||
                  (!outright && result.stage == TensorVerificationStage::FREE_SPACE &&
                   result.free_space_violation <= kRivalFreeSpaceFactor * params_.verification.free_space_fraction);
              return verified && (!accept_ || accept_ (result));
            }

            /** Whether \a rival, which rivalPasses(), is dismissed rather than a doubt on \a kept: it has
              * fewer fine correspondences, and the other sensor's background speaks against it alone
              * (TensorRegistrationParams::rival_empty_space_margin). */
            bool
            dismissed (const TensorVerificationResult& rival, const TensorVerificationResult& kept)
            {
              const double margin = params_.rival_empty_space_margin;
              if (!(margin > 0.0) || rival.fine_correspondences >= kept.fine_correspondences)
                return false;
              const double against = verification_.emptySpaceViolation (rival.transform, margin);
              return against >= params_.rival_empty_space_fraction &&
                     verification_.emptySpaceViolation (kept.transform, margin) <= kKeptEmptySpaceRatio * against;
            }

            /** A second pose, other than \a kept's, that the matches after \a from also verify (rivalPasses())
              * and that is not dismissed(); the matches whose hypothesis is near \a kept's are taken as
              * leading to it and skipped. */
            bool
            findRival (const std::vector<TensorMatch>& matches, std::size_t from, const TensorCloud::ConstPtr& batch,
                       const TensorVerificationResult& kept)
            {
              const Eigen::Matrix4f& pose = kept.transform;
              int checks = 0;
              for (std::size_t k = from; k < matches.size () && checks < params_.ambiguity_checks; ++k)
              {
                const Eigen::Matrix4f hypothesis = transformFromTensorMatch (matches[k], *model_tensors_, *batch);
                if (posesAgree (hypothesis, pose, scene_centroid_, params_.ambiguity_rotation, far_distance_) || refuted_.contains (hypothesis))
                  continue;
                ++checks;
                ++report_.ambiguity_checks;
                TensorVerificationResult result;
                if ((passes (matches[k], batch, hypothesis, result) || rivalPasses (result, false, false)) &&
                    !posesAgree (result.transform, pose, scene_centroid_, params_.repeat_rotation,
                                 params_.repeat_translation * report_.resolution) &&
                    !dismissed (result, kept))
                {
                  report_.rival_transform = result.transform;
                  return true;
                }
              }
              return false;
            }

            /** The step along \a conditioning's least constrained motion (motionPoses()) that takes \a pose
              * kValleyMargin times as far as another answer is (kRivalRotation, kRivalTranslation). */
            double
            valleyStep (const PoseConditioning& conditioning, const Eigen::Matrix4f& pose) const
            {
              const auto unit = motionPoses (conditioning, pose, 1, {1.0});
              if (unit.empty ())
                return 0.0;
              const double turn = 2.0 * std::acos (std::min (1.0, cosHalfAngleBetween (unit[0], pose))) * 180.0 / M_PI;
              const double move = static_cast<double> (((unit[0] - pose) * scene_centroid_).norm ()) / report_.resolution;
              const double step = std::min (turn > 0.0 ? kRivalRotation / turn : 1.0, move > 0.0 ? kRivalTranslation / move : 1.0);
              return kValleyMargin * std::min (step, 1.0);
            }

            /** \a best moved both ways along its least constrained motion just past another answer's
              * distance (valleyStep()) and judged as it is: a pose the views pin down loses its fit there,
              * one in a valley (a surface of revolution) that D alone cuts short keeps it. A probe that passes
              * goes to \a passed, one that is evidence enough for a rival (outright) to \a rivals, when it
              * keeps kValleyFit of \a best's fine correspondences: with fewer, the views tell them apart. */
            void
            probeValley (const PoseConditioning& conditioning, const TensorVerificationResult& best,
                         std::vector<TensorVerificationResult>& passed, std::vector<TensorVerificationResult>& rivals)
            {
              for (const Eigen::Matrix4f& pose : motionPoses (conditioning, best.transform, 1, {valleyStep (conditioning, best.transform)}))
              {
                ++report_.ambiguity_checks;
                TensorVerificationResult result;
                const bool outright = verification_.verify (pose, result, false) && (!accept_ || accept_ (result));
                if ((outright || (!result.passed () && rivalPasses (result, true, true))) &&
                    result.fine_correspondences >= kValleyFit * best.fine_correspondences)
                  (outright ? passed : rivals).push_back (result);
              }
            }

            /** The rival poses near \a best (rivalPoses()) that pass verification and the acceptor: the
              * one with the most fine correspondences replaces \a best. True when another distinct pose
              * that is evidence enough for a rival (rivalPasses()) has nearly as many (rival_margin) and is
              * not dismissed(): the views do not pin the pose down. */
            bool
            probeRivals (TensorVerificationResult& best)
            {
              if (!params_.probe_rivals)
                return false;
              const PoseConditioning conditioning = verification_.poseConditioning (best.transform);
              const double distance = params_.repeat_translation * report_.resolution;
              // A rival is another answer, not the same pose where ICP stopped (kRivalRotation, kRivalTranslation).
              const double rival_distance = kRivalTranslation * report_.resolution;
              std::vector<TensorVerificationResult> passed{best}, rivals;
              const auto probe = [&] (const Eigen::Matrix4f& pose, bool outright) {
                ++report_.ambiguity_checks;
                // Most probes of a pose the views pin down return to it under ICP: no rival, no checks.
                const Eigen::Matrix4f refined = verification_.refine (pose);
                if (posesAgree (refined, best.transform, scene_centroid_, params_.repeat_rotation, distance))
                  return;
                TensorVerificationResult result;
                if (verification_.verify (refined, result, false) && (!accept_ || accept_ (result)))
                  passed.push_back (result);
                else if (!result.passed () && rivalPasses (result, true, outright))
                  rivals.push_back (result);
              };
              probeValley (conditioning, best, passed, rivals);
              for (const Eigen::Matrix4f& pose : rivalPoses (conditioning, best.transform, 2, kRivalSteps))
                probe (pose, false);
              // A far turn of a near-symmetric object (an ellipsoid) meets poses that almost fit: from
              // there, only a pose that passes outright (D aside) doubts the answer.
              for (const Eigen::Matrix4f& pose : screwTurnPoses (conditioning, best.transform, kRivalTurns))
                probe (pose, true);
              // Only a pose that passed outright may replace the answer; any may doubt it.
              const auto strongest = std::max_element (passed.begin (), passed.end (), [] (const auto& a, const auto& b) {
                return a.fine_correspondences < b.fine_correspondences;
              });
              best = *strongest;
              rivals.insert (rivals.end (), passed.begin (), passed.end ());
              for (const auto& r : rivals)
                if (r.fine_correspondences >= (1.0 - params_.rival_margin) * best.fine_correspondences &&
                    !posesAgree (r.transform, best.transform, scene_centroid_, kRivalRotation, rival_distance) &&
                    !dismissed (r, best))
                {
                  report_.rival_transform = r.transform;
                  return true;
                }
              return false;
            }

            /** \a search run with the rivals' ICP (TensorRegistrationParams::rival_icp_max_normal_angle);
              * the answer's is restored after. */
            template <typename Search> bool
            withRivalIcp (Search search)
            {
              const TensorVerificationParams answer = verification_.getParams ();
              TensorVerificationParams rival = answer;
              rival.icp_max_normal_angle = params_.rival_icp_max_normal_angle;
              verification_.setParams (rival);
              const bool found = search ();
              verification_.setParams (answer);
              return found;
            }

            /** Verify the first \a count of \a matches in order; all of them may serve as rivals. */
            bool
            verify (const std::vector<TensorMatch>& matches, std::size_t count, const TensorCloud::ConstPtr& batch,
                    std::size_t first)
            {
              for (std::size_t k = 0; k < count; ++k)
              {
                if (capReached ())
                  return true;
                const TensorMatch& match = matches[k];
                const Eigen::Matrix4f hypothesis = transformFromTensorMatch (match, *model_tensors_, *batch);
                if (refuted_.contains (hypothesis) || refuted_answers_.contains (hypothesis))
                {
                  ++report_.hypotheses_skipped;
                  continue;
                }
                ++report_.hypotheses_tried;
                TensorVerificationResult result;
                if (!passes (match, batch, hypothesis, result))
                {
                  if (result.stage != TensorVerificationStage::PASSED)
                    ++report_.failures[static_cast<std::size_t> (result.stage)];
                  continue;
                }
                // Two poses that both verify: no evidence picks one, so neither is reported.
                report_.ambiguous = withRivalIcp ([&] { return findRival (matches, k + 1, batch, result) || probeRivals (result); });
                report_.registered = !report_.ambiguous;
                report_.winning_match = match;
                report_.winning_match.scene += static_cast<decltype (match.scene)> (first);
                report_.verification = result;
                if (report_.registered)
                  report_.transform = result.transform;
                return true;
              }
              return capReached ();
            }

            TensorCloud::ConstPtr model_tensors_;
            const TensorRegistrationParams& params_;
            TensorRegistrationReport& report_;
            const HypothesisAcceptor& accept_;
            CorrespondenceRejectorTensorVerification verification_;
            RefutedHypotheses refuted_{0.0, 0.0};
            /** Refused by the free-space check: a close repeat is no answer either, but may still doubt
              * one as a rival (rivalPasses()), so findRival() does not skip it. */
            RefutedHypotheses refuted_answers_{0.0, 0.0};
            std::vector<RefutedHypotheses> icp_dead_ends_;  ///< per ICP stage (addDeadEnds())
            Eigen::Vector4f scene_centroid_;  ///< where poses are compared (homogeneous)
            double far_distance_;             ///< mean(D) / 2: a pose moving the centroid farther is another pose
            std::vector<TensorMatch> deferred_;  ///< scene indices into all batches' tensors
            std::vector<TensorMatch> below_thresholds_;  ///< below t_r or t_c: the second round's; indices as deferred_'s
        };

        /** The scene's tensors batch by batch, each matched and verified before the next (Fig. 7). */
        void
        searchInBatches (HypothesisSearch& hypotheses, const TensorView& scene, const TensorCloud::Ptr& scene_tensors,
                         const ObjectDimensions& dims, const TensorRegistrationParams& params, TensorRegistrationReport& report)
        {
          const auto budget = static_cast<std::size_t> (params.batch_hypotheses);
          // One estimation for every batch: the scene is meshed and its pairs formed once.
          ViewTensorEstimation estimation;
          configureViewEstimation (estimation, *scene.scan, dims, params);
          for (int batch = 0; batch < params.scene_tensor_batches; ++batch)
          {
            pcl::StopWatch watch;
            estimation.setPairBatch (params.scene_tensor_batches, batch);
            const TensorCloud::Ptr tensors (new TensorCloud);
            estimation.computeOrThrow (*tensors);
            report.timings.tensors_ms += watch.getTime ();
            const std::size_t first = scene_tensors->size ();
            *scene_tensors += *tensors;
            report.scene_tensors = scene_tensors->size ();
            if (!tensors->empty () && hypotheses.search (tensors, first, budget))
              return;
          }
          hypotheses.finish (scene_tensors);
        }
      }

      void
      searchTensorViews (const TensorView& model, const TensorView& scene, const ObjectDimensions& dims,
                         const TensorRegistrationParams& params, const HypothesisAcceptor& accept,
                         const Eigen::Matrix4f* guess, TensorRegistrationReport& report)
      {
        TensorCloud::ConstPtr model_tensors = model.tensors;
        if (!model_tensors)
        {
          pcl::StopWatch watch;
          model_tensors = computeViewTensors (*model.scan, dims, params);
          report.timings.tensors_ms += watch.getTime ();
        }
        resetReport (report, model_tensors->size (), dims);
        // Every batch joins the scene's tensors, so that the winning match's index refers to them all.
        const TensorCloud::Ptr batches (new TensorCloud);
        const TensorCloud::ConstPtr scene_tensors = scene.tensors ? scene.tensors : batches;
        report.scene_tensors = scene.tensors ? scene.tensors->size () : 0;
        // A view without tensors (a plane: no two normals theta_d apart) matches nothing; only a guess
        // can still register it.
        const bool nothing_to_match = model_tensors->empty () || (scene.tensors && scene.tensors->empty ());
        if (nothing_to_match && !guess)
          return;
        HypothesisSearch hypotheses (model, model_tensors, scene, scene_tensors, dims, params, report, accept);
        if ((guess && hypotheses.tryGuess (*guess)) || nothing_to_match)
          return;
        if (scene.tensors)
          hypotheses.search (scene.tensors, 0);
        else
          searchInBatches (hypotheses, scene, batches, dims, params, report);
        hypotheses.searchBelowThresholds (scene_tensors);
      }
    }
  }
}
