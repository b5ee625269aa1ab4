/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/features/tensor_descriptor.h>
#include <pcl/point_cloud.h>

#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace pcl
{
  namespace registration
  {
    /** \brief One match between a scene tensor and a model tensor (Section 4).
      * \ingroup registration
      */
    struct TensorMatch
    {
      int model = -1;             ///< index of the model tensor T_m
      int scene = -1;             ///< index of the scene tensor T_s
      bool scene_flipped = false; ///< the scene tensor was matched in its swapped pair order (flipPairOrder)
      float correlation = 0.0f;   ///< C_c over the overlapping bins (Eq. 6): the score
      float overlap_ratio = 0.0f; ///< R_O = n_q / (n_m + n_s - n_q) (Eq. 5)
      int n_q = 0;                ///< number of bins non-zero in both tensors
    };

    /** \brief The set of non-zero bins of a tensor as a bitset, so that n_q, and with it R_O (Eq. 5),
      * costs a few AND and popcount instructions instead of a pass over the bins. Matching tests R_O
      * first and computes C_c only for the few pairs that pass t_r.
      * \ingroup registration
      */
    class TensorBinSet
    {
      public:
        TensorBinSet () = default;
        explicit TensorBinSet (const TensorDescriptor& tensor);

        /** \brief n_q: bins non-zero in both tensors (of the same grid size). */
        int countShared (const TensorBinSet& other) const;

        /** \brief Number of non-zero bins. */
        int size () const { return size_; }

      private:
        std::vector<std::uint64_t> words_;
        int size_{0};
    };

    /** \brief R_O of Eq. 5 from the bin counts, exactly as TensorComparator::compare computes it. */
    inline float
    overlapRatio (int n_q, std::size_t n_m, std::size_t n_s)
    {
      const double union_bins = static_cast<double> (n_m) + static_cast<double> (n_s) - n_q;
      return union_bins > 0.0 ? static_cast<float> (n_q / union_bins) : 0.0f;
    }

    /** \brief Whether \a match passes Section 4's thresholds: R_O >= t_r (Eq. 5) and C_c >= t_c (Eq. 6). */
    inline bool
    passesThresholds (const TensorMatch& match, float t_r, float t_c)
    {
      return match.overlap_ratio >= t_r && match.correlation >= t_c;
    }

    /** \brief Compares one scene tensor against many model tensors quickly: the scene tensor is
      * scattered once into a dense grid, then each model tensor costs one pass over its non-zero bins.
      * \ingroup registration
      */
    class TensorComparator
    {
      public:
        /** \brief Load the scene tensor \a scene (bins sorted by index, as TensorEstimation gives them). */
        void setScene (const TensorDescriptor& scene);

        /** \brief Eq. 5 and Eq. 6 between the loaded scene tensor and \a model.
          * \param[in] model a model tensor with the same grid size
          * \param[out] match overlap_ratio, n_q and correlation (0 when fewer than 2 bins overlap or a
          *             side is constant over the overlap, since Eq. 6 is then undefined)
          */
        void compare (const TensorDescriptor& model, TensorMatch& match) const;

      private:
        std::vector<float> dense_;
        std::vector<std::uint32_t> stamp_;
        std::uint32_t epoch_{0};
        std::size_t scene_bins_{0};
    };

    /** \brief The rigid transform that aligns the scene tensor's frame with the model tensor's, taking
      * scene points into the model's frame (Eq. 7 and 8). The paper multiplies row vectors,
      * p_m = p_s R + t with R = B_s^T B_m and t = O_m - O_s R; with PCL's column vectors this is
      * p_m = R' p_s + t' with R' = B_m^T B_s and t' = O_m - R' O_s, where the rows of B are the frame's
      * x, y and z axes (TensorDescriptor::rf).
      * \ingroup registration
      */
    Eigen::Matrix4f
    transformFromTensorPair (const TensorDescriptor& model, const TensorDescriptor& scene);

    /** \brief The hypothesis of one match (Eq. 7-8): transformFromTensorPair() of its model tensor and
      * its scene tensor, in the pair order that matched (TensorMatch::scene_flipped), without copying
      * the bins as flipPairOrder() does.
      * \param[in] match its indices refer to \a model_tensors and \a scene_tensors
      */
    Eigen::Matrix4f
    transformFromTensorMatch (const TensorMatch& match, const pcl::PointCloud<TensorDescriptor>& model_tensors,
                              const pcl::PointCloud<TensorDescriptor>& scene_tensors);
  }
}
