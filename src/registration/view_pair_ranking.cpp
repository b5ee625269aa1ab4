/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/registration/view_pair_ranking.h>
#include "../common/parallel_for.h"
#include <pcl/common/tensor_exceptions.h>
#include <pcl/features/tensor_index.h>
#include <pcl/registration/tensor_match.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace pcl
{
  namespace registration
  {
    namespace
    {
      /** Matches of one sampled tensor that propose poses (its best by C_c). */
      constexpr std::size_t kProposalsPerTensor = 3;
    }

    /** One view's tensors ready for matching: the theta_d index, the bin sets and the sample. */
    struct ViewPairRanking::IndexedView
    {
      pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr tensors;
      TensorThetaIndex index;
      std::vector<TensorBinSet> bins;
      std::vector<int> sample;
      Eigen::Vector3f centre = Eigen::Vector3f::Zero ();  ///< the mean of the tensors' origins
      double size = 0.0;                                  ///< mean(D) the tensors were computed with
    };

    ViewPairRanking::ViewPairRanking (const std::vector<TensorView::ConstPtr>& views, const TensorRegistrationParams& params,
                                      const ViewPairRankingParams& ranking)
      : views_ (views.size ()), params_ (params), agreement_degrees_ (ranking.agreement_degrees),
        agreement_distance_ (ranking.agreement_distance)
    {
      if (ranking.sample_tensors < 0)
        PCL_TENSOR_THROW (BadArgumentException, "the ranking's sample must be 0 (all) or positive, got " << ranking.sample_tensors);
      for (std::size_t i = 0; i < views.size (); ++i)
      {
        if (!views[i] || !views[i]->tensors || views[i]->tensors->empty ())
          continue;
        auto v = std::make_shared<IndexedView> ();
        v->tensors = views[i]->tensors;
        v->index.setBinWidth (params.theta_bin_width);
        v->index.build (*v->tensors);
        v->bins.reserve (v->tensors->size ());
        for (const auto& t : *v->tensors)
          v->bins.emplace_back (t);
        const std::size_t n = v->tensors->size ();
        const std::size_t k = ranking.sample_tensors > 0 ? std::min<std::size_t> (n, ranking.sample_tensors) : n;
        // Evenly spread over the list, which runs over the view's vertex pairs in order.
        for (std::size_t s = 0; s < k; ++s)
          v->sample.push_back (static_cast<int> ((2 * s + 1) * n / (2 * k)));
        for (const auto& t : *v->tensors)
          v->centre += t.getVector3fMap ();
        v->centre /= static_cast<float> (n);
        v->size = views[i]->dimensions.mean ();
        views_[i] = v;
      }
    }

    namespace
    {
      /** A pose one tensor match proposes (Eq. 7-8), with its correlation. */
      struct Proposal
      {
        Eigen::Matrix3f rotation;
        Eigen::Vector3f centre;  ///< where the pose puts the scene's centre
        float correlation;
      };

      /** The most proposals that agree with one of them: within \a cos_half of its rotation and
        * \a distance of where it puts the scene's centre. */
      std::size_t
      largestAgreement (const std::vector<Proposal>& proposals, float cos_half, float distance)
      {
        std::size_t best = 0;
        for (const auto& p : proposals)
        {
          std::size_t agree = 0;
          for (const auto& q : proposals)
          {
            const float trace = (p.rotation * q.rotation.transpose ()).trace ();
            if (0.5f * std::sqrt (std::max (0.0f, 1.0f + trace)) >= cos_half && (p.centre - q.centre).norm () <= distance)
              ++agree;
          }
          best = std::max (best, agree);
        }
        return best;
      }
    }

    double
    ViewPairRanking::oneWay (const IndexedView& model, const IndexedView& scene) const
    {
      TensorComparator comparator;
      std::vector<Proposal> proposals;
      std::vector<std::pair<float, int>> found;
      for (const int s : scene.sample)
      {
        const TensorDescriptor& tensor = (*scene.tensors)[s];
        const auto propose = [&] (const TensorDescriptor& t, const TensorBinSet& bins) {
          found.clear ();
          bool loaded = false;
          for (const int m : model.index.candidates (t.theta_d))
          {
            const int n_q = bins.countShared (model.bins[m]);
            if (overlapRatio (n_q, model.bins[m].size (), bins.size ()) < params_.overlap_threshold)
              continue;
            if (!loaded)
            {
              comparator.setScene (t);
              loaded = true;
            }
            TensorMatch match;
            comparator.compare ((*model.tensors)[m], match);
            if (passesThresholds (match, params_.overlap_threshold, params_.correlation_threshold))
              found.emplace_back (match.correlation, m);
          }
          // The best few of each tensor: a true partner is among them, and more would only add noise.
          const std::size_t keep = std::min<std::size_t> (found.size (), kProposalsPerTensor);
          std::partial_sort (found.begin (), found.begin () + keep, found.end (), std::greater<> ());
          for (std::size_t k = 0; k < keep; ++k)
          {
            const Eigen::Matrix4f pose = transformFromTensorPair ((*model.tensors)[found[k].second], t);
            proposals.push_back ({pose.topLeftCorner<3, 3> (), pose.topLeftCorner<3, 3> () * scene.centre + pose.topRightCorner<3, 1> (),
                                  found[k].first});
          }
        };
        propose (tensor, scene.bins[s]);
        if (tensor.order_ambiguous)
        {
          const TensorDescriptor flipped = flipPairOrder (tensor);
          propose (flipped, TensorBinSet (flipped));
        }
      }
      const float distance = static_cast<float> (agreement_distance_ * std::max (model.size, scene.size));
      const std::size_t agree = largestAgreement (proposals, static_cast<float> (std::cos (agreement_degrees_ * M_PI / 360.0)), distance);
      return scene.sample.empty () ? 0.0 : static_cast<double> (agree) / static_cast<double> (scene.sample.size ());
    }

    double
    ViewPairRanking::score (int a, int b) const
    {
      const auto valid = [&] (int i) { return i >= 0 && static_cast<std::size_t> (i) < views_.size () && views_[i]; };
      if (a == b || !valid (a) || !valid (b))
        return 0.0;
      return 0.5 * (oneWay (*views_[a], *views_[b]) + oneWay (*views_[b], *views_[a]));
    }

    std::vector<ViewPairCandidate>
    ViewPairRanking::rank (const std::vector<std::pair<int, int>>& allowed, unsigned threads, const ViewPairScoreMemo& known) const
    {
      std::vector<ViewPairCandidate> pairs;
      const auto add = [&] (int a, int b) {
        if (a != b && views_[std::min (a, b)] && views_[std::max (a, b)])
          pairs.push_back ({std::min (a, b), std::max (a, b), 0.0});
      };
      const int n = static_cast<int> (views_.size ());
      if (allowed.empty ())
        for (int a = 0; a < n; ++a)
          for (int b = a + 1; b < n; ++b)
            add (a, b);
      for (const auto& p : allowed)
        if (p.first >= 0 && p.second >= 0 && p.first < n && p.second < n)
          add (p.first, p.second);
      std::sort (pairs.begin (), pairs.end (), [] (const auto& x, const auto& y) {
        return std::tie (x.first, x.second) < std::tie (y.first, y.second);
      });
      pairs.erase (std::unique (pairs.begin (), pairs.end (), [] (const auto& x, const auto& y) {
        return x.first == y.first && x.second == y.second;
      }), pairs.end ());
      std::vector<std::size_t> unknown;
      for (std::size_t k = 0; k < pairs.size (); ++k)
        if (!known.find || !known.find (pairs[k].first, pairs[k].second, pairs[k].score))
          unknown.push_back (k);
      pcl::detail::parallelFor (unknown.size (), threads, [&] (std::size_t u) {
        auto& pair = pairs[unknown[u]];
        pair.score = score (pair.first, pair.second);
      });
      if (known.keep)
      {
        std::vector<ViewPairCandidate> scored;
        scored.reserve (unknown.size ());
        for (const std::size_t k : unknown)
          scored.push_back (pairs[k]);
        known.keep (scored);
      }
      std::stable_sort (pairs.begin (), pairs.end (), [] (const auto& x, const auto& y) { return x.score > y.score; });
      return pairs;
    }
  }
}
