/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/features/tensor_descriptor.h>
#include <pcl/features/tensor_index.h>
#include <pcl/registration/correspondence_estimation.h>
#include <pcl/registration/tensor_match.h>

#include <string>
#include <vector>

namespace pcl
{
  namespace registration
  {
    /** \brief The order in which tensor matches are offered as registration hypotheses. */
    enum class TensorMatchOrder
    {
      /** The paper's (Fig. 7): scene tensors in order; each one's matches best first. */
      SCENE_ORDER,
      /** All matches of all scene tensors, highest correlation C_c first. */
      BEST_FIRST
    };

    /** \brief The order's name on a command line: "scene" or "best". */
    const char*
    tensorMatchOrderName (TensorMatchOrder order);

    /** \brief The order named \a name (tensorMatchOrderName()).
      * \throw pcl::BadArgumentException for any other name */
    TensorMatchOrder
    parseTensorMatchOrder (const std::string& name);

    /** \brief Put \a matches in \a order (stable: ties keep their order). */
    void
    sortTensorMatches (std::vector<TensorMatch>& matches, TensorMatchOrder order);

    /** \brief Matches the tensors of a scene view (source) against those of a model view (target),
      * as Section 4 does: each scene tensor is compared with the model tensors at theta_d +- Delta
      * theta_d in the index table; a pair matches when the overlap ratio R_O (Eq. 5) reaches t_r and
      * the correlation coefficient C_c over the overlapping bins (Eq. 6) reaches t_c.
      *
      * Each correspondence has index_query = scene tensor, index_match = model tensor and
      * distance = 1 - C_c, so that PCL's lower-is-better conventions hold; getMatches() gives C_c,
      * R_O and n_q beside it, in the same order. Scene tensors whose pair order is ambiguous
      * (TensorDescriptor::order_ambiguous) are also tried in the swapped order.
      * \ingroup registration
      */
    class CorrespondenceEstimationTensor
      : public CorrespondenceEstimationBase<pcl::TensorDescriptor, pcl::TensorDescriptor, float>
    {
      public:
        using Ptr = shared_ptr<CorrespondenceEstimationTensor>;
        using ConstPtr = shared_ptr<const CorrespondenceEstimationTensor>;
        using Base = CorrespondenceEstimationBase<pcl::TensorDescriptor, pcl::TensorDescriptor, float>;

        CorrespondenceEstimationTensor () { corr_name_ = "CorrespondenceEstimationTensor"; }

        /** \brief Set t_r, the minimum overlap ratio R_O of Eq. 5 (Section 4: 0.5). */
        void setOverlapThreshold (float t_r);
        float getOverlapThreshold () const { return overlap_threshold_; }

        /** \brief Set t_c, the minimum correlation coefficient C_c of Eq. 6 (Section 4: 0.5). */
        void setCorrelationThreshold (float t_c);
        float getCorrelationThreshold () const { return correlation_threshold_; }

        /** \brief Set Delta theta_d of the index table, in degrees (Section 2: 5). */
        void setThetaBinWidth (double degrees);
        double getThetaBinWidth () const { return theta_bin_width_; }

        /** \brief Compare through the theta_d index (default) or every tensor with every tensor
          * (to measure the index's speed-up, Eq. 13).
          */
        void setUseThetaIndex (bool use) { use_theta_index_ = use; }
        bool getUseThetaIndex () const { return use_theta_index_; }

        /** \brief Set the order of the output (default TensorMatchOrder::BEST_FIRST).
          * \note The default departs from Fig. 7's SCENE_ORDER: the likeliest hypotheses are verified
          * first; see doc/design.md#best-first-order. */
        void setOrder (TensorMatchOrder order) { order_ = order; }
        TensorMatchOrder getOrder () const { return order_; }

        /** \brief All matches that pass t_r and t_c, in the configured order.
          * \param[out] correspondences scene tensor -> model tensor, distance = 1 - C_c
          * \param[in] max_distance drop matches with 1 - C_c above this
          * \throw pcl::BadArgumentException when an input is missing or the grid sizes differ
          */
        void
        determineCorrespondences (pcl::Correspondences& correspondences,
                                  double max_distance = std::numeric_limits<double>::max ()) override;

        /** \brief The matches that are each other's best: the scene tensor's best model tensor is that
          * model tensor's best scene tensor.
          */
        void
        determineReciprocalCorrespondences (pcl::Correspondences& correspondences,
                                            double max_distance = std::numeric_limits<double>::max ()) override;

        /** \brief Details of the last call's correspondences, index for index. */
        const std::vector<TensorMatch>& getMatches () const { return matches_; }

        /** \brief Number of tensor comparisons of the last call (mu in Eq. 13). */
        std::size_t getComparisons () const { return comparisons_; }

        Base::Ptr
        clone () const override
        {
          return Ptr (new CorrespondenceEstimationTensor (*this));
        }

      private:
        /** All matches above the thresholds, unordered. */
        std::vector<TensorMatch> matchAll ();
        void checkInputs () const;
        /** Drop matches over \a max_distance, then mirror matches_ into \a correspondences. */
        void toCorrespondences (double max_distance, pcl::Correspondences& correspondences);

        float overlap_threshold_{0.5f};
        float correlation_threshold_{0.5f};
        double theta_bin_width_{5.0};
        bool use_theta_index_{true};
        TensorMatchOrder order_{TensorMatchOrder::BEST_FIRST};
        std::vector<TensorMatch> matches_;
        std::size_t comparisons_{0};
    };
  }
}
