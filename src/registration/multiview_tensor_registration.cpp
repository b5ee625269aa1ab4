/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/registration/multiview_tensor_registration.h>
#include "../common/parallel_for.h"
#include "ranked_view_registration.h"
#include <pcl/common/tensor_exceptions.h>
#include <pcl/common/time.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <mutex>
#include <set>

namespace pcl
{
  namespace registration
  {
    std::string
    toString (MultiviewStage stage)
    {
      switch (stage)
      {
        case MultiviewStage::PREPARATION: return "meshing";
        case MultiviewStage::TENSORS: return "tensors";
        case MultiviewStage::PAIRWISE: return "pairwise";
        case MultiviewStage::GLOBAL: return "global";
      }
      return "unknown";
    }

    std::size_t
    MultiviewRegistrationResult::registeredCount () const
    {
      return static_cast<std::size_t> (std::count_if (views.begin (), views.end (), [] (const auto& v) { return v.registered; }));
    }

    namespace
    {
      bool
      finiteAtLeast (double value, double low)
      {
        return std::isfinite (value) && value >= low;
      }

      void
      checkGlobalStepParams (const MultiviewIcpParams& p)
      {
        if (p.max_iterations < 0 || p.sample_points < 1 || !(std::isfinite (p.max_distance) && p.max_distance > 0.0))
          PCL_TENSOR_THROW (BadArgumentException, "the global step needs non-negative iterations, a positive sample and "
                            "a positive pairing distance, got " << p.max_iterations << ", " << p.sample_points << " and "
                            << p.max_distance);
        if (!(p.max_normal_angle > 0.0 && p.max_normal_angle <= 180.0) || !finiteAtLeast (p.min_rotation, 0.0) ||
            !finiteAtLeast (p.min_translation, 0.0))
          PCL_TENSOR_THROW (BadArgumentException, "the global step's normal angle must lie in (0, 180] degrees and its "
                            "convergence tolerances be finite and non-negative");
      }
    }

    void
    checkParams (const MultiviewRegistrationParams& params)
    {
      checkParams (params.pairwise);
      const auto& g = params.global_verification;
      if (!finiteAtLeast (g.tolerance, 0.0) || g.checked_dimensions < 1 || g.checked_dimensions > 3)
        PCL_TENSOR_THROW (BadArgumentException, "global verification needs a finite non-negative tolerance and 1 to 3 "
                          "checked dimensions, got " << g.tolerance << " and " << g.checked_dimensions);
      const Eigen::Vector3d& d = params.object_dimensions;
      if (!d.allFinite () || (d.array () < 0.0).any () || (!d.isZero () && !(d.array () > 0.0).all ()))
        PCL_TENSOR_THROW (BadArgumentException, "object dimensions must be three positive numbers, or all zero (from "
                          "the views), got " << d.transpose ());
      if (params.max_references < 0 || params.max_failed_pairs < 0 || params.ranking.sample_tensors < 0 ||
          params.first_pass_hypotheses < 0 || params.second_pass_pairs < 0)
        PCL_TENSOR_THROW (BadArgumentException, "max_references, max_failed_pairs, the ranking's sample, first_pass_hypotheses and second_pass_pairs "
                          "must be 0 (no limit) or positive, got " << params.max_references << ", " << params.max_failed_pairs
                          << ", " << params.ranking.sample_tensors << ", " << params.first_pass_hypotheses << " and "
                          << params.second_pass_pairs);
      if (params.max_overlap_pairs < 0)
        PCL_TENSOR_THROW (BadArgumentException, "max_overlap_pairs must be 0 (all) or positive, got " << params.max_overlap_pairs);
      if (!(params.min_overlap >= 0.0 && params.min_overlap <= 1.0))
        PCL_TENSOR_THROW (BadArgumentException, "min_overlap must lie in [0, 1], got " << params.min_overlap);
      checkGlobalStepParams (params.global);
    }

    namespace
    {
      /** A view's meshes' frame -> its own frame: the meshes are centred on the view's origin
        * (prepareTensorView), unless the caller gave them prepared otherwise. */
      Eigen::Affine3d
      meshToView (const ViewRegistrationStatus& v)
      {
        return Eigen::Affine3d (Eigen::Translation3d (v.view ? v.view->origin : Eigen::Vector3d::Zero ()));
      }
    }

    std::vector<pcl::IntegrationView>
    registeredIntegrationViews (const MultiviewRegistrationResult& result, int component, bool kept_poses)
    {
      std::vector<pcl::IntegrationView> views;
      for (const auto& v : result.views)
        if (v.registered && v.prepared && v.component == component && (kept_poses || !v.pose_kept))
        {
          pcl::IntegrationView r;
          r.mesh = pcl::ScanMesh::ConstPtr (v.prepared, &v.prepared->fine);
          r.pose = v.pose * meshToView (v);
          views.push_back (r);
        }
      return views;
    }

    namespace
    {
      using Views = std::vector<TensorView::ConstPtr>;

      void
      report (const MultiviewProgress& progress, MultiviewStage stage, std::size_t done, std::size_t total)
      {
        if (progress)
          progress (stage, done, total);
      }

      /** Progress of one stage whose steps finish on several threads, reported one at a time. */
      class StageProgress
      {
        public:
          StageProgress (const MultiviewProgress& progress, MultiviewStage stage, std::size_t total)
            : progress_ (progress), stage_ (stage), total_ (total) {}

          void
          step ()
          {
            const std::lock_guard<std::mutex> lock (mutex_);
            report (progress_, stage_, ++done_, total_);
          }

        private:
          const MultiviewProgress& progress_;
          MultiviewStage stage_;
          std::size_t total_, done_{0};
          std::mutex mutex_;
      };

      /** Stage 1: M_i and M'_i of every view, on \a threads threads, centred as the apps and the cache
        * centre them (prepareTensorView); a view that cannot be meshed is marked and left out (null). */
      Views
      prepareViews (const std::vector<MultiviewInput>& inputs, const MultiviewRegistrationParams& params,
                    const MultiviewProgress& progress, unsigned threads, MultiviewRegistrationResult& result)
      {
        Views meshed (inputs.size ());
        StageProgress stage (progress, MultiviewStage::PREPARATION, inputs.size ());
        pcl::detail::parallelFor (inputs.size (), threads, [&] (std::size_t i) {
          ViewRegistrationStatus& view = result.views[i];
          view.name = inputs[i].name;
          pcl::StopWatch watch;
          try
          {
            if (inputs[i].view)
              meshed[i] = inputs[i].view;
            else if (!inputs[i].cloud)
              PCL_TENSOR_THROW (InvalidScanException, "the view has no cloud");
            else
              meshed[i] = prepareTensorView (*inputs[i].cloud, inputs[i].viewpoint, params.pairwise.preparation);
            view.prepared = meshed[i]->scan;
          }
          catch (const InvalidScanException& e)
          {
            view.error = errorDescription (e);
          }
          view.prepare_ms = watch.getTime ();
          stage.step ();
        });
        return meshed;
      }

      /** D from every usable view (Eq. 1), unless it is known, and the mean d_res. */
      void
      measureObject (const MultiviewRegistrationParams& params, MultiviewRegistrationResult& result)
      {
        std::vector<const pcl::PointCloud<pcl::PointNormal>*> fine;
        double resolution = 0.0;
        for (const auto& view : result.views)
          if (view.prepared)
          {
            fine.push_back (view.prepared->fine.cloud.get ());
            resolution += view.prepared->resolution;
          }
        if (fine.empty ())
          return;
        result.dimensions = givenObjectDimensions (params.object_dimensions);
        if (!result.dimensions.isSet ())
          result.dimensions = computeObjectDimensions<pcl::PointNormal> (fine);
        result.resolution = resolution / static_cast<double> (fine.size ());
      }

      /** Stage 2: each usable view's tensors, once, on \a threads threads: the views every
        * registration takes (TensorView). */
      Views
      computeTensors (const Views& meshed, const MultiviewRegistrationParams& params, const MultiviewProgress& progress,
                      unsigned threads, MultiviewRegistrationResult& result)
      {
        Views tensors (result.views.size ());
        StageProgress stage (progress, MultiviewStage::TENSORS, result.views.size ());
        pcl::detail::parallelFor (result.views.size (), threads, [&] (std::size_t i) {
          ViewRegistrationStatus& view = result.views[i];
          if (view.prepared)
          {
            pcl::StopWatch watch;
            try
            {
              const TensorView::ConstPtr& given = meshed[i];
              if (given->tensors && given->dimensions.D == result.dimensions.D)
                tensors[i] = given;
              else
                tensors[i] = withTensors (*given, result.dimensions, params.pairwise);
              view.view = tensors[i];
            }
            catch (const InvalidScanException& e)
            {
              view.error = errorDescription (e);
            }
            view.tensors_ms = watch.getTime ();
          }
          stage.step ();
        });
        return tensors;
      }

      /** Stage 3: the registration of views one at a time, with global verification. */
      class OrderedRegistration
      {
        public:
          OrderedRegistration (const MultiviewRegistrationParams& params, const ViewPairs& pairs, const Views& tensors,
                               const detail::KnownPoses& known, unsigned threads, MultiviewRegistrationResult& result)
            : params_ (params), pairs_ (pairs), tensors_ (tensors), known_ (known), threads_ (threads), result_ (result),
              verification_ (result.dimensions, result.resolution, params.global_verification)
          {}

          /** Registers every view it can; views that fail are retried while others get registered. */
          void
          run (const MultiviewProgress& progress)
          {
            std::vector<int> pending;
            for (std::size_t i = 0; i < tensors_.size (); ++i)
              if (tensors_[i])
                pending.push_back (static_cast<int> (i));
            if (pending.empty ())
              return;
            const std::size_t total = pending.size ();
            // The views of known poses first, else the first view, define the common frame.
            const auto given = std::stable_partition (pending.begin (), pending.end (), [&] (int v) { return known_.known[v]; });
            if (given == pending.begin ())
              accept (pending.front (), -1, Eigen::Affine3d::Identity ());
            for (auto it = pending.begin (); it != given; ++it)
              accept (*it, -1, known_.poses[*it], true);
            result_.reference = pending.front ();
            pending.erase (pending.begin (), std::max (given, pending.begin () + 1));
            report (progress, MultiviewStage::PAIRWISE, registered_.size (), total);
            for (bool progressed = true; progressed && !pending.empty ();)
            {
              progressed = false;
              for (auto it = pending.begin (); it != pending.end ();)
              {
                if (registerView (*it))
                {
                  it = pending.erase (it);
                  progressed = true;
                  report (progress, MultiviewStage::PAIRWISE, registered_.size (), total);
                }
                else
                  ++it;
              }
            }
            report (progress, MultiviewStage::PAIRWISE, total, total);
          }

        private:
          /** Registered views to try for \a view, most recently registered first, not tried before. */
          std::vector<int>
          references (int view) const
          {
            std::vector<int> refs;
            for (auto it = registered_.rbegin (); it != registered_.rend (); ++it)
            {
              const bool partner = pairs_.empty () ||
                  std::any_of (pairs_.begin (), pairs_.end (), [&] (const auto& p) {
                    return (p.first == view && p.second == *it) || (p.second == view && p.first == *it);
                  });
              if (partner && !tried_.count ({*it, view}))
                refs.push_back (*it);
            }
            if (params_.max_references > 0 && refs.size () > static_cast<std::size_t> (params_.max_references))
              refs.resize (params_.max_references);
            return refs;
          }

          /** One pair on the views prepared once, with global verification. */
          TensorRegistrationReport
          registerPair (int reference, int view, const HypothesisAcceptor& global) const
          {
            return registerTensorViews (tensors_[reference], tensors_[view], result_.dimensions, params_.pairwise, global);
          }

          /** One reference tried for one view: the pair's report and the last global excess seen. */
          struct Attempt
          {
            TensorRegistrationReport pair;
            double excess = 0.0;
          };

          Attempt
          attempt (int reference, int view) const
          {
            Attempt a;
            const Eigen::Affine3d ref_pose = result_.views[reference].pairwise_pose;
            const auto& scene = *result_.views[view].prepared->fine.cloud;
            const Eigen::Affine3d to_view = meshToView (result_.views[view]);
            const HypothesisAcceptor global = [&] (const TensorVerificationResult& local) {
              const Eigen::Affine3d pose = ref_pose * Eigen::Affine3d (local.transform.cast<double> ());
              a.excess = verification_.excess (scene, pose * to_view);
              return a.excess <= params_.global_verification.tolerance;
            };
            a.pair = registerPair (reference, view, global);
            return a;
          }

          /** Tries the references of \a view, most recently registered first, and keeps the first that
            * registers (or, with keep_best, the one of largest overlap). After the first, several are tried
            * at once on threads_ threads, but their results are taken in order and those after the first success
            * are dropped, so the outcome is the one of trying them one at a time. */
          bool
          registerView (int view)
          {
            ViewRegistrationStatus& status = result_.views[view];
            const std::size_t scene_points = status.prepared->fine.cloud->size ();
            pcl::StopWatch watch;
            double best_overlap = -1.0;
            const std::vector<int> refs = references (view);
            // The most recent reference alone first: in an ordered set it is the one that registers, and
            // trying others beside it would only slow it down.
            const std::size_t batch = params_.keep_best ? refs.size () : pcl::detail::threadCount (threads_);
            bool done = false;
            for (std::size_t first = 0, size = params_.keep_best ? batch : 1; first < refs.size () && !done;
                 first += size, size = batch)
            {
              std::vector<Attempt> attempts (std::min (size, refs.size () - first));
              pcl::detail::parallelFor (attempts.size (), threads_, [&] (std::size_t k) { attempts[k] = attempt (refs[first + k], view); });
              for (std::size_t k = 0; k < attempts.size () && !done; ++k)
              {
                const int ref = refs[first + k];
                const TensorRegistrationReport& pair = attempts[k].pair;
                tried_.insert ({ref, view});
                ++status.references_tried;
                status.globally_refused += pair.hypotheses_refused;
                const double overlap = pair.verification.fine_correspondences / static_cast<double> (scene_points);
                if (pair.registered && overlap > best_overlap)
                {
                  best_overlap = overlap;
                  status.pairwise = pair;
                  status.reference = ref;
                  status.global_excess = attempts[k].excess;
                  done = !params_.keep_best;
                }
                else if (best_overlap < 0.0)
                  status.pairwise = pair;
              }
            }
            status.pairwise_ms += watch.getTime ();
            if (best_overlap < 0.0)
              return false;
            accept (view, status.reference,
                    result_.views[status.reference].pairwise_pose * Eigen::Affine3d (status.pairwise.transform.cast<double> ()));
            return true;
          }

          void
          accept (int view, int reference, const Eigen::Affine3d& pose, bool kept = false)
          {
            ViewRegistrationStatus& status = result_.views[view];
            status.registered = true;
            status.pose_kept = kept;
            status.reference = reference;
            status.pairwise_pose = status.pose = pose;
            verification_.addView (*status.prepared->fine.cloud, pose * meshToView (status));
            registered_.push_back (view);
          }

          const MultiviewRegistrationParams& params_;
          const ViewPairs& pairs_;
          const Views& tensors_;
          const detail::KnownPoses& known_;
          const unsigned threads_;
          MultiviewRegistrationResult& result_;
          GlobalVerification verification_;
          std::vector<int> registered_;          ///< in the order they were registered
          std::set<std::pair<int, int>> tried_;  ///< (reference, view) pairs already tried
      };

      /** The pairs that overlap by min_overlap under the pairwise poses, each view's max_overlap_pairs
        * most overlapping (a pair stays when it is among either view's): many views around an object
        * overlap many others, and the global step's cost grows with its pairs, its accuracy hardly. */
      ViewPairs
      mostOverlapping (const MultiviewRegistrationParams& params, const std::vector<const ScanMesh*>& meshes,
                       const ViewPoses& poses, const ViewPairs& candidates, double resolution, unsigned threads)
      {
        std::vector<double> fractions;
        const ViewPairs found = selectOverlappingPairs (meshes, poses, candidates, resolution, params.global.max_distance,
                                                        params.min_overlap, 500, threads, &fractions);
        if (params.max_overlap_pairs <= 0)
          return found;
        std::vector<std::vector<std::pair<double, std::size_t>>> of_view (meshes.size ());
        for (std::size_t k = 0; k < found.size (); ++k)
        {
          of_view[found[k].first].emplace_back (-fractions[k], k);
          of_view[found[k].second].emplace_back (-fractions[k], k);
        }
        std::set<std::size_t> kept;
        for (auto& list : of_view)
        {
          std::sort (list.begin (), list.end ());  // most overlapping first; ties: lower pair first
          for (std::size_t r = 0; r < list.size () && r < static_cast<std::size_t> (params.max_overlap_pairs); ++r)
            kept.insert (list[r].second);
        }
        ViewPairs pairs;
        for (const std::size_t k : kept)
          pairs.push_back (found[k]);
        return pairs;
      }

      /** The pairs of the global step within one component: registration's own, the loop, given
        * pairs, found overlaps; of those, the pairs with a view that moves (not \a fixed). */
      ViewPairs
      globalPairs (const MultiviewRegistrationParams& params, const ViewPairs& given, const std::vector<const ScanMesh*>& meshes,
                   const ViewPoses& poses, const std::vector<bool>& fixed, const MultiviewRegistrationResult& result,
                   int component, unsigned threads)
      {
        std::set<std::pair<int, int>> pairs;
        std::vector<bool> member (result.views.size ());
        for (std::size_t i = 0; i < result.views.size (); ++i)
          member[i] = result.views[i].registered && result.views[i].component == component;
        const auto useful = [&] (int a, int b) { return a != b && member[a] && member[b] && !(fixed[a] && fixed[b]); };
        const auto add = [&] (int a, int b) {
          if (a >= 0 && b >= 0 && useful (a, b))
            pairs.insert ({std::min (a, b), std::max (a, b)});
        };
        int first = -1, last = -1;
        for (std::size_t i = 0; i < result.views.size (); ++i)
          if (member[i])
            (first < 0 ? first : last) = static_cast<int> (i);
        for (const auto& p : result.joins)
          add (p.first, p.second);
        if (params.loop)
          add (first, last);
        for (const auto& p : given)
          add (p.first, p.second);
        if (params.min_overlap > 0.0)
        {
          ViewPairs candidates;
          for (int a = 0; a < static_cast<int> (member.size ()); ++a)
            for (int b = a + 1; b < static_cast<int> (member.size ()); ++b)
              if (useful (a, b))
                candidates.emplace_back (a, b);
          for (const auto& p : mostOverlapping (params, meshes, poses, candidates, result.resolution, threads))
            add (p.first, p.second);
        }
        return ViewPairs (pairs.begin (), pairs.end ());
      }

      /** The views of one component that the global step keeps still: those of kept poses, else the
        * one registered to no other (its frame is the component's). */
      std::vector<bool>
      fixedViews (const MultiviewRegistrationResult& result, int component)
      {
        std::vector<bool> fixed (result.views.size (), false);
        bool any = false;
        for (std::size_t i = 0; i < result.views.size (); ++i)
          if (result.views[i].registered && result.views[i].component == component && result.views[i].pose_kept)
            any = fixed[i] = true;
        for (std::size_t i = 0; i < result.views.size () && !any; ++i)
          if (result.views[i].registered && result.views[i].component == component && result.views[i].reference < 0)
            any = fixed[i] = true;
        return fixed;
      }

      /** Stage 4: the registered views of each component moved together (Section 5, module 5 of Fig. 9);
        * the result's global step is component 0's. */
      void
      registerGlobally (const MultiviewRegistrationParams& params, const ViewPairs& given, const MultiviewProgress& progress,
                        unsigned threads, MultiviewRegistrationResult& result)
      {
        const std::size_t steps = static_cast<std::size_t> (std::max (params.global.max_iterations, 1));
        for (int c = 0; c < result.components; ++c)
        {
          std::vector<const ScanMesh*> meshes (result.views.size (), nullptr);
          ViewPoses poses (result.views.size (), Eigen::Affine3d::Identity ());
          for (std::size_t i = 0; i < result.views.size (); ++i)
            if (result.views[i].registered && result.views[i].component == c)
            {
              meshes[i] = &result.views[i].prepared->fine;
              poses[i] = result.views[i].pairwise_pose * meshToView (result.views[i]);
            }
          const std::vector<bool> fixed = fixedViews (result, c);
          const ViewPairs pairs = globalPairs (params, given, meshes, poses, fixed, result, c, threads);
          result.pairs.insert (result.pairs.end (), pairs.begin (), pairs.end ());
          if (pairs.empty ())
            continue;
          const MultiviewIcpProgress icp_progress = [&] (int it, int max_it) {
            if (c == 0)
              report (progress, MultiviewStage::GLOBAL, static_cast<std::size_t> (it), static_cast<std::size_t> (max_it));
          };
          MultiviewIcpResult global = multiviewPointToPlaneIcp (meshes, poses, pairs, fixed, result.resolution, params.global,
                                                                 icp_progress, threads);
          for (std::size_t i = 0; i < result.views.size (); ++i)
            if (result.views[i].registered && result.views[i].component == c && !fixed[i])
              result.views[i].pose = global.poses[i] * meshToView (result.views[i]).inverse ();
          if (c == 0)
            result.global = std::move (global);
        }
        std::sort (result.pairs.begin (), result.pairs.end ());
        report (progress, MultiviewStage::GLOBAL, steps, steps);  // done, also when it converged early
      }

      /** ORDERED: one component of every registered view, joined as registration went. */
      void
      orderedComponents (MultiviewRegistrationResult& result)
      {
        for (std::size_t i = 0; i < result.views.size (); ++i)
          if (result.views[i].registered)
          {
            result.views[i].component = 0;
            result.components = 1;
            if (result.views[i].reference >= 0)
              result.joins.emplace_back (std::min<int> (i, result.views[i].reference), std::max<int> (i, result.views[i].reference));
          }
      }

      void
      checkInputs (const std::vector<MultiviewInput>& views)
      {
        for (const auto& v : views)
        {
          if (v.view && !v.view->scan)
            PCL_TENSOR_THROW (BadArgumentException, "view " << v.name << " is given prepared without meshes");
          if (v.pose_known && !(v.known_pose.matrix ().allFinite () && v.known_pose.linear ().isUnitary (1e-6) &&
                                v.known_pose.linear ().determinant () > 0.0))
            PCL_TENSOR_THROW (BadArgumentException, "view " << v.name << " is given a known pose that is not a rigid motion");
        }
      }

      /** The usable views whose poses are given. */
      detail::KnownPoses
      knownPoses (const std::vector<MultiviewInput>& inputs, const Views& tensors)
      {
        detail::KnownPoses known;
        known.known.assign (inputs.size (), false);
        known.poses.assign (inputs.size (), Eigen::Affine3d::Identity ());
        for (std::size_t i = 0; i < inputs.size (); ++i)
          if (inputs[i].pose_known && tensors[i])
          {
            known.known[i] = true;
            known.poses[i] = inputs[i].known_pose;
          }
        return known;
      }

      void
      checkPairs (const ViewPairs& pairs, std::size_t n)
      {
        for (const auto& p : pairs)
          if (p.first < 0 || p.second < 0 || static_cast<std::size_t> (p.first) >= n || static_cast<std::size_t> (p.second) >= n ||
              p.first == p.second)
            PCL_TENSOR_THROW (BadArgumentException, "overlapping pair (" << p.first << ", " << p.second << ") is not a pair of two of the "
                              << n << " views");
      }
    }

    MultiviewRegistrationResult
    MultiviewTensorRegistration::compute (const std::vector<MultiviewInput>& views) const
    {
      checkPairs (pairs_, views.size ());
      checkInputs (views);
      pcl::StopWatch total, watch;
      MultiviewRegistrationResult result;
      result.views.resize (views.size ());
      const Views meshed = prepareViews (views, params_, progress_, threads_, result);
      measureObject (params_, result);
      result.timings.prepare_ms = watch.getTime ();
      if (result.resolution <= 0.0)
        return result;  // no usable view: none is registered, each says why

      watch.reset ();
      const Views tensors = computeTensors (meshed, params_, progress_, threads_, result);
      result.timings.tensors_ms = watch.getTime ();

      watch.reset ();
      const detail::KnownPoses known = knownPoses (views, tensors);
      if (params_.search == ViewSearch::ORDERED)
      {
        OrderedRegistration (params_, pairs_, tensors, known, threads_, result).run (progress_);
        orderedComponents (result);
      }
      else
      {
        const ViewPairRegistration registration = pair_registration_ ? pair_registration_ :
            [] (int, int, const TensorView::ConstPtr& model, const TensorView::ConstPtr& scene, const ObjectDimensions& dims,
                const TensorRegistrationParams& params) { return registerTensorViews (model, scene, dims, params); };
        detail::registerRankedViews (params_, pairs_, tensors, known, registration, pair_scores_, threads_, progress_, result);
      }
      result.timings.pairwise_ms = watch.getTime ();

      watch.reset ();
      if (params_.global_registration)
        registerGlobally (params_, pairs_, progress_, threads_, result);
      result.timings.global_ms = watch.getTime ();
      result.timings.total_ms = total.getTime ();
      return result;
    }
  }
}
