/*
 * pcl_tensor: multiview registration of views in any order (private to the library): a view graph
 * grown from ranked pairs, Kruskal-like, with global verification of every join.
 */
#include "ranked_view_registration.h"
#include "../common/parallel_for.h"
#include "../common/union_find.h"

#include <pcl/common/time.h>

#include <algorithm>
#include <map>
#include <memory>

namespace pcl
{
  namespace registration
  {
    namespace detail
    {
      namespace
      {
        /** Pairs registered at once. Fixed, not the thread count, so that the result is the same on any
          * number of threads; the pairs of one batch close no loop among groups, so none is wasted. */
        constexpr std::size_t kPairBatch = 8;

        /** Verification keeps each view's z-buffers for its other pairs (TensorView::projections), about
          * 1 MB a view: those of views in none of the last few batches are dropped, so that memory does
          * not grow with the number of views (208 views: 788 MB without the z-buffers, 1,016 MB keeping all). */
        constexpr std::size_t kZBufferBatches = 4;

        /** The tree that joins the views of each group, rooted at the group's reference view. */
        class JoinTree
        {
          public:
            explicit JoinTree (std::size_t n) : parent_ (n, -1) {}

            /** Make \a v the root of its tree, turning the path to the old root around. */
            void
            reroot (int v, std::vector<ViewRegistrationStatus>& status)
            {
              int child = v, previous = -1;
              TensorRegistrationReport carried;
              while (child >= 0)
              {
                const int up = parent_[child];
                TensorRegistrationReport edge = status[child].pairwise;
                parent_[child] = previous;
                if (previous >= 0)
                  status[child].pairwise = invertedTransform (carried);
                carried = edge;
                previous = child;
                child = up;
              }
            }

            void link (int child, int parent) { parent_[child] = parent; }
            int parent (int v) const { return parent_[v]; }

            /** The report with its transform turned around (the rest as registered). */
            static TensorRegistrationReport
            invertedTransform (TensorRegistrationReport report)
            {
              report.transform = Eigen::Matrix4f (report.transform.inverse ());
              return report;
            }

          private:
            std::vector<int> parent_;
        };

        class RankedRegistration
        {
          public:
            RankedRegistration (const MultiviewRegistrationParams& params, const std::vector<TensorView::ConstPtr>& views,
                                const KnownPoses& known, const ViewPairRegistration& registration, unsigned threads,
                                MultiviewRegistrationResult& result)
              : params_ (params), views_ (views), registration_ (registration), threads_ (threads), result_ (result),
                group_of_ (views.size (), -1), pose_ (views.size (), Eigen::Affine3d::Identity ()), failed_ (views.size (), 0),
                tree_ (views.size ())
            {
              // Each view's own check (its convex hull) is independent of the others': made on every core.
              std::vector<std::shared_ptr<GlobalVerification>> checks (views.size ());
              pcl::detail::parallelFor (views.size (), threads, [&] (std::size_t i) {
                if (!views[i])
                  return;
                checks[i] = std::make_shared<GlobalVerification> (result.dimensions, result.resolution, params.global_verification);
                // Poses are between the views' own frames; the meshes may be centred on origin.
                checks[i]->addView (*views[i]->scan->fine.cloud, Eigen::Affine3d (Eigen::Translation3d (views[i]->origin)));
              });
              if (known.any ())
                joinKnown (known, checks);
              for (std::size_t i = 0; i < views.size (); ++i)
                if (checks[i] && group_of_[i] < 0)
                {
                  group_of_[i] = static_cast<int> (groups_.size ());
                  Group g;
                  g.members.push_back (static_cast<int> (i));
                  g.check = std::move (checks[i]);
                  groups_.push_back (g);
                }
              usable_ = 0;
              for (const auto& g : groups_)
                usable_ += g.members.size ();
            }

            void
            run (const ViewPairs& allowed, const ViewPairScoreCache& scores, const MultiviewProgress& progress)
            {
              if (largestGroup () == usable_)
              {
                assignComponents ();  // nothing to register: every view's pose is known
                return;
              }
              pcl::StopWatch ranking;
              ViewPairScoreMemo known = scores ? scores (result_.dimensions, params_.pairwise, params_.ranking) : ViewPairScoreMemo ();
              known.keep = [this, keep = known.keep] (const std::vector<ViewPairCandidate>& scored) {
                result_.candidates_scored = scored.size ();
                if (keep)
                  keep (scored);
              };
              result_.candidates = ViewPairRanking (views_, params_.pairwise, params_.ranking).rank (pairsToRank (allowed), threads_, known);
              result_.timings.ranking_ms = ranking.getTime ();
              TensorRegistrationParams quick = params_.pairwise;
              const int budget = params_.first_pass_hypotheses;
              if (budget > 0 && (quick.max_hypotheses == 0 || budget < quick.max_hypotheses))
              {
                quick.max_hypotheses = budget;
                // Pairs the first pass refused only for want of hypotheses get the full search later.
                std::vector<char> retry (result_.candidates.size (), 0);
                pass (quick, false, progress, retry);
                std::fill (failed_.begin (), failed_.end (), 0);
                std::vector<char> skip (retry.size ());
                for (std::size_t c = 0; c < retry.size (); ++c)
                  skip[c] = !retry[c];
                retry_limit_ = params_.second_pass_pairs;
                pass (params_.pairwise, true, progress, skip);
              }
              else
              {
                std::vector<char> decided (result_.candidates.size (), 0);
                pass (params_.pairwise, true, progress, decided);
              }
              assignComponents ();
            }

          private:
            /** The views of given poses as one group, in the frame of their poses (its reference: the
              * lowest index among them); their own checks are merged into the group's. */
            void
            joinKnown (const KnownPoses& known, std::vector<std::shared_ptr<GlobalVerification>>& checks)
            {
              Group g;
              g.known = true;
              g.check = std::make_shared<GlobalVerification> (result_.dimensions, result_.resolution, params_.global_verification);
              for (std::size_t i = 0; i < views_.size (); ++i)
                if (checks[i] && known.known[i])
                {
                  g.check->merge (*checks[i], known.poses[i]);
                  checks[i].reset ();
                  g.members.push_back (static_cast<int> (i));
                  group_of_[i] = static_cast<int> (groups_.size ());
                  pose_[i] = known.poses[i];
                  kept_[i] = true;
                }
              if (!g.members.empty ())
                groups_.push_back (g);
            }

            /** The pairs to rank: \a allowed (empty: all), less those within the group of known poses. */
            ViewPairs
            pairsToRank (const ViewPairs& allowed) const
            {
              const bool known = !groups_.empty () && groups_.front ().known;
              if (!known)
                return allowed;
              ViewPairs pairs;
              const auto add = [&] (int a, int b) {
                if (group_of_[a] < 0 || group_of_[b] < 0 || !(groups_[group_of_[a]].known && groups_[group_of_[b]].known))
                  pairs.emplace_back (a, b);
              };
              if (!allowed.empty ())
                for (const auto& p : allowed)
                  add (p.first, p.second);
              else
                for (int a = 0; a < static_cast<int> (views_.size ()); ++a)
                  for (int b = a + 1; b < static_cast<int> (views_.size ()); ++b)
                    add (a, b);
              return pairs;
            }

            /** A registered pair and the time it took on its core. */
            struct Registered
            {
              TensorRegistrationReport report;
              double ms = 0.0;
            };

            /** One pass over the candidates not \a decided, best first; on return \a decided marks the
              * candidates a pass with more hypotheses could still join (refused at the cap). */
            void
            pass (const TensorRegistrationParams& params, bool full, const MultiviewProgress& progress, std::vector<char>& decided)
            {
              std::vector<char> capped (decided.size (), 0);
              retried_.clear ();
              std::map<std::size_t, Registered> ahead;  // registered before their batch, on cores left idle
              for (std::vector<std::size_t> batch; !(batch = nextBatch (decided)).empty ();)
              {
                std::vector<std::size_t> work;
                for (const std::size_t c : batch)
                  if (ahead.find (c) == ahead.end ())
                    work.push_back (c);
                const std::size_t cores = pcl::detail::threadCount (threads_);
                const std::vector<std::size_t> next = nextCandidates (decided, batch, ahead, (cores - work.size () % cores) % cores);
                work.insert (work.end (), next.begin (), next.end ());
                std::vector<Registered> done (work.size ());
                pcl::detail::parallelFor (work.size (), threads_, [&] (std::size_t k) {
                  const ViewPairCandidate& c = result_.candidates[work[k]];
                  pcl::StopWatch watch;
                  done[k].report = registration_ (c.first, c.second, views_[c.first], views_[c.second], result_.dimensions, params);
                  done[k].ms = watch.getTime ();
                });
                for (std::size_t k = 0; k < work.size (); ++k)
                  ahead[work[k]] = std::move (done[k]);
                dropIdleZBuffers (work);
                for (const std::size_t c : batch)
                {
                  decided[c] = 1;
                  const Registered registered = std::move (ahead.at (c));
                  ahead.erase (c);
                  const TensorRegistrationReport& r = registered.report;
                  capped[c] = !r.registered && !r.ambiguous && params.max_hypotheses > 0 &&
                              r.hypotheses_tried >= static_cast<std::size_t> (params.max_hypotheses);
                  take (result_.candidates[c], r, registered.ms);
                  result_.attempts.back ().full = full;
                }
                if (progress)
                  progress (MultiviewStage::PAIRWISE, largestGroup (), usable_);
              }
              result_.pairs_registered_ahead_unused += ahead.size ();
              decided = capped;
              for (const auto& v : views_)
                if (v && v->projections)
                  v->projections->clear ();
            }

            /** Marks the views of the pairs just registered as in use, and drops the z-buffers of views in
              * none of the last kZBufferBatches batches (a later pair builds them again, the same). */
            void
            dropIdleZBuffers (const std::vector<std::size_t>& registered)
            {
              ++batches_;
              for (const std::size_t c : registered)
                for (const int v : {result_.candidates[c].first, result_.candidates[c].second})
                  last_batch_[v] = batches_;
              for (std::size_t v = 0; v < views_.size (); ++v)
                if (views_[v] && views_[v]->projections && last_batch_[v] + kZBufferBatches <= batches_)
                  views_[v]->projections->clear ();
            }

            struct Group
            {
              std::vector<int> members;  ///< members.front () is the group's reference view
              std::shared_ptr<GlobalVerification> check;
              bool known = false;        ///< it holds the views of known poses (its frame is theirs)
            };

            std::size_t
            largestGroup () const
            {
              std::size_t largest = 0;
              for (const auto& g : groups_)
                largest = std::max (largest, g.members.size ());
              return largest;
            }

            /** The second pass registers a few pairs between two groups, the best ranked: if their
              * views overlap, those are the likeliest to show it, and refusals are slow. */
            bool
            retriesSpent (int a, int b) const
            {
              if (retry_limit_ <= 0)
                return false;
              const auto it = retried_.find ({std::min (a, b), std::max (a, b)});
              return it != retried_.end () && it->second >= retry_limit_;
            }

            bool
            givenUp (int view) const
            {
              return params_.max_failed_pairs > 0 && failed_[view] >= params_.max_failed_pairs;
            }

            /** The next candidates, best first, that join distinct groups and close no loop among the
              * groups with the batch's other pairs: whichever of them pass, each joins two groups still
              * apart when its turn comes. A group may be in several pairs, so a batch stays full when one
              * group has grown around most views. */
            std::vector<std::size_t>
            nextBatch (std::vector<char>& decided)
            {
              std::vector<std::size_t> batch;
              if (largestGroup () == usable_)
                return batch;
              pcl::detail::UnionFind linked (groups_.size ());
              for (std::size_t c = 0; c < decided.size () && batch.size () < kPairBatch; ++c)
              {
                if (decided[c])
                  continue;
                const ViewPairCandidate& p = result_.candidates[c];
                const int a = group_of_[p.first], b = group_of_[p.second];
                if (a == b || givenUp (p.first) || givenUp (p.second) || retriesSpent (a, b))
                {
                  decided[c] = 1;  // already joined, a view given up, or enough tries between the groups
                  continue;
                }
                if (linked.find (a) == linked.find (b))
                  continue;  // would close a loop with this batch's pairs: waits for the next batch
                linked.unite (a, b);
                batch.push_back (c);
                if (retry_limit_ > 0)
                  ++retried_[{std::min (a, b), std::max (a, b)}];
              }
              return batch;
            }

            /** Up to \a count candidates that the batches after \a batch would take first, as things stand:
              * registered now, they keep the cores busy that a short batch (two groups left, one pair
              * each) leaves idle. A pair's registration depends on nothing but the pair, so when its
              * batch comes the result is the same; if it never comes, only an idle core's time is lost. */
            std::vector<std::size_t>
            nextCandidates (const std::vector<char>& decided, const std::vector<std::size_t>& batch,
                            const std::map<std::size_t, Registered>& ahead, std::size_t count) const
            {
              std::vector<std::size_t> next;
              for (std::size_t c = 0; c < decided.size () && next.size () < count; ++c)
              {
                if (decided[c] || ahead.find (c) != ahead.end () || std::find (batch.begin (), batch.end (), c) != batch.end ())
                  continue;
                const ViewPairCandidate& p = result_.candidates[c];
                const int a = group_of_[p.first], b = group_of_[p.second];
                if (a != b && !givenUp (p.first) && !givenUp (p.second) && !retriesSpent (a, b))
                  next.push_back (c);
              }
              return next;
            }

            /** One registered pair: the two groups are joined when it passed and their union passes global
              * verification. */
            void
            take (const ViewPairCandidate& pair, const TensorRegistrationReport& report, double ms)
            {
              ViewPairAttempt attempt;
              attempt.first = pair.first;
              attempt.second = pair.second;
              attempt.score = pair.score;
              attempt.registered = report.registered;
              attempt.ms = ms;
              result_.attempts.push_back (attempt);
              const int a = pair.first, b = pair.second;
              auto& status = result_.views;
              for (const int v : {a, b})
              {
                ++status[v].references_tried;
                status[v].pairwise_ms += ms;
              }
              if (!report.registered)
              {
                ++failed_[a];
                ++failed_[b];
                for (const int v : {a, b})
                  if (!status[v].registered && tree_.parent (v) < 0)
                    status[v].pairwise = report;  // why it failed, until it is joined
                return;
              }
              // The group of b moved into a's group frame: pose_a * T(b -> a) * pose_b^-1.
              const Eigen::Affine3d b_to_a (report.transform.cast<double> ());
              const Eigen::Affine3d move = pose_[a] * b_to_a * pose_[b].inverse ();
              const Group& ga = groups_[group_of_[a]];
              const Group& gb = groups_[group_of_[b]];
              const double excess = ga.check->excess (*gb.check, move);
              result_.attempts.back ().excess = excess;
              if (excess > params_.global_verification.tolerance)
              {
                ++status[a].globally_refused;
                ++status[b].globally_refused;
                ++failed_[a];
                ++failed_[b];
                return;
              }
              result_.attempts.back ().joined = true;
              // The group of known poses keeps its frame, else the one whose reference has the lower index.
              if (ga.known || (!gb.known && ga.members.front () < gb.members.front ()))
                join (a, b, move, report, excess);
              else
                join (b, a, move.inverse (), JoinTree::invertedTransform (report), excess);
            }

            /** Joins \a child's group into \a parent's, \a move taking the child group's frame into the
              * parent's; \a report's transform takes \a child into \a parent's frame. */
            void
            join (int parent, int child, const Eigen::Affine3d& move, const TensorRegistrationReport& report, double excess)
            {
              Group& into = groups_[group_of_[parent]];
              Group& from = groups_[group_of_[child]];
              into.check->merge (*from.check, move);
              into.known = into.known || from.known;
              tree_.reroot (child, result_.views);
              tree_.link (child, parent);
              result_.views[child].pairwise = report;
              result_.views[child].global_excess = excess;
              result_.joins.emplace_back (std::min (parent, child), std::max (parent, child));
              const int target = group_of_[parent];
              for (const int v : from.members)
              {
                pose_[v] = move * pose_[v];
                group_of_[v] = target;
                into.members.push_back (v);
              }
              from.members.clear ();
              from.check.reset ();
            }

            /** Groups of two views or more become components, largest first (ties: lower reference
              * index); when no pair joined, the first usable view alone is component 0, as in ORDERED. */
            void
            assignComponents ()
            {
              std::vector<const Group*> order;
              for (const auto& g : groups_)
                if (g.members.size () > 1 || g.known)
                  order.push_back (&g);
              if (order.empty () && !groups_.empty ())
                order.push_back (&groups_.front ());
              std::stable_sort (order.begin (), order.end (), [] (const Group* x, const Group* y) {
                return x->members.size () > y->members.size () ||
                       (x->members.size () == y->members.size () && x->members.front () < y->members.front ());
              });
              for (std::size_t c = 0; c < order.size (); ++c)
                for (const int v : order[c]->members)
                {
                  ViewRegistrationStatus& s = result_.views[v];
                  s.registered = true;
                  s.pose_kept = kept_[v];
                  s.component = static_cast<int> (c);
                  s.reference = tree_.parent (v);
                  s.pairwise_pose = s.pose = pose_[v];
                  if (s.reference < 0)
                    s.pairwise = TensorRegistrationReport ();  // the reference was joined by others' pairs
                }
              result_.components = static_cast<int> (order.size ());
              result_.reference = order.empty () ? -1 : order.front ()->members.front ();
            }

            const MultiviewRegistrationParams& params_;
            const std::vector<TensorView::ConstPtr>& views_;
            const ViewPairRegistration& registration_;
            const unsigned threads_;
            MultiviewRegistrationResult& result_;
            std::vector<Group> groups_;
            std::vector<int> group_of_;
            std::vector<Eigen::Affine3d, Eigen::aligned_allocator<Eigen::Affine3d>> pose_;  ///< view -> its group's frame
            std::vector<int> failed_;
            JoinTree tree_;
            std::size_t usable_ = 0;
            int retry_limit_ = 0;                       ///< second pass: pairs per two groups (0: no limit)
            std::size_t batches_ = 0;                   ///< batches registered so far
            std::vector<std::size_t> last_batch_ = std::vector<std::size_t> (views_.size (), 0);  ///< per view: the last batch it was in
            std::map<std::pair<int, int>, int> retried_;  ///< pairs registered per two groups
            std::vector<bool> kept_ = std::vector<bool> (views_.size (), false);  ///< per view: its pose was given
        };
      }

      void
      registerRankedViews (const MultiviewRegistrationParams& params, const ViewPairs& allowed,
                           const std::vector<TensorView::ConstPtr>& views, const KnownPoses& known,
                           const ViewPairRegistration& registration, const ViewPairScoreCache& scores, unsigned threads,
                           const MultiviewProgress& progress, MultiviewRegistrationResult& result)
      {
        RankedRegistration (params, views, known, registration, threads, result).run (allowed, scores, progress);
      }
    }
  }
}
