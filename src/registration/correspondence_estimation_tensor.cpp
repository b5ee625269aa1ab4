/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/registration/correspondence_estimation_tensor.h>
#include <pcl/common/tensor_exceptions.h>
// The base class owns kd-trees over tensors; PCL does not precompile them for our point type.
#include <pcl/impl/pcl_base.hpp>
#include <pcl/kdtree/impl/kdtree_flann.hpp>
#include <pcl/search/impl/kdtree.hpp>
#include <pcl/search/impl/search.hpp>

#include <algorithm>
#include <map>
#include <numeric>

namespace pcl
{
  namespace registration
  {
    void
    CorrespondenceEstimationTensor::setOverlapThreshold (float t_r)
    {
      if (!(t_r >= 0.0f && t_r <= 1.0f))
        PCL_TENSOR_THROW (BadArgumentException, "overlap threshold t_r must be in [0, 1], got " << t_r);
      overlap_threshold_ = t_r;
    }

    void
    CorrespondenceEstimationTensor::setCorrelationThreshold (float t_c)
    {
      if (!(t_c >= -1.0f && t_c <= 1.0f))
        PCL_TENSOR_THROW (BadArgumentException, "correlation threshold t_c must be in [-1, 1], got " << t_c);
      correlation_threshold_ = t_c;
    }

    void
    CorrespondenceEstimationTensor::setThetaBinWidth (double degrees)
    {
      if (!(degrees > 0.0 && degrees <= 180.0))
        PCL_TENSOR_THROW (BadArgumentException, "theta_d bin width must be in (0, 180] degrees, got " << degrees);
      theta_bin_width_ = degrees;
    }

    void
    CorrespondenceEstimationTensor::checkInputs () const
    {
      if (!input_ || !target_)
        PCL_TENSOR_THROW (BadArgumentException, "tensor matching needs scene tensors (source) and model tensors (target)");
      if (!input_->empty () && !target_->empty () && input_->front ().grid_size != target_->front ().grid_size)
        PCL_TENSOR_THROW (BadArgumentException, "scene tensors have grid size " << input_->front ().grid_size
                          << ", model tensors " << target_->front ().grid_size);
    }

    std::vector<TensorMatch>
    CorrespondenceEstimationTensor::matchAll ()
    {
      checkInputs ();
      TensorThetaIndex index (theta_bin_width_);
      index.build (*target_);
      std::vector<int> everything (target_->size ());
      std::iota (everything.begin (), everything.end (), 0);

      std::vector<TensorBinSet> model_bins (target_->begin (), target_->end ());
      std::vector<TensorMatch> matches;
      TensorComparator comparator;
      comparisons_ = 0;
      auto match_scene = [&] (const TensorDescriptor& scene, int scene_index, bool flipped) {
        const TensorBinSet scene_bins (scene);
        bool scene_loaded = false;
        const TensorThetaIndex::Range range = use_theta_index_ ? index.candidates (scene.theta_d)
            : TensorThetaIndex::Range{everything.data (), everything.data () + everything.size ()};
        for (const int m : range)
        {
          ++comparisons_;
          // R_O from the bitsets first: most candidates fail t_r, and C_c is needed only for the rest.
          const int n_q = scene_bins.countShared (model_bins[m]);
          if (overlapRatio (n_q, model_bins[m].size (), scene_bins.size ()) < overlap_threshold_)
            continue;
          if (!scene_loaded)
          {
            comparator.setScene (scene);
            scene_loaded = true;
          }
          TensorMatch match;
          comparator.compare ((*target_)[m], match);
          if (!passesThresholds (match, overlap_threshold_, correlation_threshold_))
            continue;
          match.model = m;
          match.scene = scene_index;
          match.scene_flipped = flipped;
          matches.push_back (match);
        }
      };
      for (int s = 0; s < static_cast<int> (input_->size ()); ++s)
      {
        const TensorDescriptor& scene = (*input_)[s];
        match_scene (scene, s, false);
        if (scene.order_ambiguous)
          match_scene (flipPairOrder (scene), s, true);
      }
      return matches;
    }

    void
    CorrespondenceEstimationTensor::toCorrespondences (double max_distance, pcl::Correspondences& correspondences)
    {
      matches_.erase (std::remove_if (matches_.begin (), matches_.end (),
                                      [&] (const TensorMatch& m) { return 1.0 - m.correlation > max_distance; }),
                      matches_.end ());
      correspondences.clear ();
      correspondences.reserve (matches_.size ());
      for (const auto& m : matches_)
        correspondences.emplace_back (m.scene, m.model, 1.0f - m.correlation);
    }

    const char*
    tensorMatchOrderName (TensorMatchOrder order)
    {
      switch (order)
      {
        case TensorMatchOrder::SCENE_ORDER: return "scene";
        case TensorMatchOrder::BEST_FIRST: return "best";
      }
      return "unknown";
    }

    TensorMatchOrder
    parseTensorMatchOrder (const std::string& name)
    {
      for (const TensorMatchOrder order : {TensorMatchOrder::SCENE_ORDER, TensorMatchOrder::BEST_FIRST})
        if (name == tensorMatchOrderName (order))
          return order;
      PCL_TENSOR_THROW (pcl::BadArgumentException, "match order must be 'scene' or 'best', got '" << name << "'");
    }

    void
    sortTensorMatches (std::vector<TensorMatch>& matches, TensorMatchOrder order)
    {
      auto better = [] (const TensorMatch& a, const TensorMatch& b) { return a.correlation > b.correlation; };
      if (order == TensorMatchOrder::BEST_FIRST)
        std::stable_sort (matches.begin (), matches.end (), better);
      else
        std::stable_sort (matches.begin (), matches.end (), [&] (const TensorMatch& a, const TensorMatch& b) {
          return a.scene != b.scene ? a.scene < b.scene : better (a, b);
        });
    }

    void
    CorrespondenceEstimationTensor::determineCorrespondences (pcl::Correspondences& correspondences, double max_distance)
    {
      matches_ = matchAll ();
      sortTensorMatches (matches_, order_);
      toCorrespondences (max_distance, correspondences);
    }

    void
    CorrespondenceEstimationTensor::determineReciprocalCorrespondences (pcl::Correspondences& correspondences, double max_distance)
    {
      const std::vector<TensorMatch> all = matchAll ();
      std::map<int, const TensorMatch*> best_of_scene, best_of_model;
      for (const auto& m : all)
      {
        auto& s = best_of_scene[m.scene];
        if (!s || m.correlation > s->correlation)
          s = &m;
        auto& t = best_of_model[m.model];
        if (!t || m.correlation > t->correlation)
          t = &m;
      }
      matches_.clear ();
      for (const auto& [scene, match] : best_of_scene)
        if (best_of_model[match->model] == match)
          matches_.push_back (*match);
      std::stable_sort (matches_.begin (), matches_.end (),
                        [] (const TensorMatch& a, const TensorMatch& b) { return a.correlation > b.correlation; });
      toCorrespondences (max_distance, correspondences);
    }
  }
}

template class pcl::PCLBase<pcl::TensorDescriptor>;
template class pcl::KdTreeFLANN<pcl::TensorDescriptor>;
template class pcl::search::Search<pcl::TensorDescriptor>;
template class pcl::search::KdTree<pcl::TensorDescriptor>;
