/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/registration/tensor_registration_params.h>
#include <pcl/registration/tensor_view.h>

#include <functional>
#include <vector>

namespace pcl
{
  namespace registration
  {
    /** \brief Settings of ViewPairRanking. */
    struct ViewPairRankingParams
    {
      /** Tensors of each view, spread evenly over its list, matched against every tensor of the
        * other view (0: all). The cost of a pair grows with it, its power to tell neighbours from
        * strangers saturates early (doc/design.md#ranking-view-pairs). */
      int sample_tensors = 48;
      /** Two proposed poses agree within this rotation (degrees) ... */
      double agreement_degrees = 12.0;
      /** ... and when they put the scene's centre within this fraction of mean(D) of each other
        * (t_D of Section 4.1 is 0.1). */
      double agreement_distance = 0.1;
    };

    /** \brief A pair of views (indices) and how promising it is: higher first. */
    struct ViewPairCandidate
    {
      int first = -1;
      int second = -1;
      /** The largest set of agreeing poses proposed by the sampled tensors' matches, per sampled
        * tensor, averaged over both directions. */
      double score = 0.0;
    };

    /** \brief Scores of view pairs known from before, e.g. kept in a cache across runs, so that a run with
      * views added scores only the new pairs. Either function may be empty. Both are called from the
      * thread that calls ViewPairRanking::rank().
      */
    struct ViewPairScoreMemo
    {
      /** Sets \a score of views \a a < \a b and returns true when it is known. */
      std::function<bool (int a, int b, double& score)> find;
      /** Told, once per ranking, the pairs scored because find() did not know them. */
      std::function<void (const std::vector<ViewPairCandidate>& scored)> keep;
    };

    /** \brief Which pairs of many unordered views are worth a full registration, from their tensors
      * alone (beyond the paper, which registers views in a known order): a sample of each view's
      * tensors is matched (Eq. 5 and 6, thresholds t_r and t_c, the theta_d index of Section 4)
      * against all of the other's; each of a sampled tensor's best matches proposes a pose (Eq. 7-8),
      * and the pair scores the largest number of proposals that agree on one pose. Tensors of
      * overlapping views that match their true partners agree; chance matches between any two
      * surfaces scatter. Nothing is verified: the score only orders the pairs that registration
      * then verifies.
      * \ingroup registration
      */
    class ViewPairRanking
    {
      public:
        /** \param[in] views views with tensors (null entries: unusable views, never ranked)
          * \param[in] params t_r, t_c and the theta_d bin width of matching
          * \param[in] ranking the sample size */
        ViewPairRanking (const std::vector<TensorView::ConstPtr>& views, const TensorRegistrationParams& params,
                         const ViewPairRankingParams& ranking = {});

        /** \brief The score of views \a a and \a b (symmetric); 0 when either is unusable. */
        double score (int a, int b) const;

        /** \brief Every pair of usable views, or only \a allowed when it is not empty, best first
          * (ties: lower indices first), scored on \a threads threads (0: every core), save those that
          * \a known already holds: a score it gives must be score()'s, bit for bit, for the ranking
          * to be the same. */
        std::vector<ViewPairCandidate>
        rank (const std::vector<std::pair<int, int>>& allowed = {}, unsigned threads = 0,
              const ViewPairScoreMemo& known = {}) const;

      private:
        struct IndexedView;
        /** Mean best correlation of \a scene's sample against every tensor of \a model. */
        double oneWay (const IndexedView& model, const IndexedView& scene) const;

        std::vector<std::shared_ptr<const IndexedView>> views_;
        TensorRegistrationParams params_;
        double agreement_degrees_, agreement_distance_;
    };
  }
}
