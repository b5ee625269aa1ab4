/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/registration/tensor_match.h>

#include <algorithm>
#include <cmath>

namespace pcl
{
  namespace registration
  {
    TensorBinSet::TensorBinSet (const TensorDescriptor& tensor)
      : words_ ((static_cast<std::size_t> (tensor.denseSize ()) + 63) / 64, 0u)
      , size_ (static_cast<int> (tensor.bin_index.size ()))
    {
      for (const std::uint16_t bin : tensor.bin_index)
        words_[bin / 64] |= std::uint64_t{1} << (bin % 64);
    }

// Without -mpopcnt, which a distributed build cannot assume, __builtin_popcountll is a libgcc call,
// slow enough to show in a whole pair registration (figures: doc/log.md); GCC's clones pick the
// instruction at load time where the CPU has it.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
    __attribute__ ((target_clones ("popcnt", "default")))
#endif
    int
    TensorBinSet::countShared (const TensorBinSet& other) const
    {
      const std::size_t n = std::min (words_.size (), other.words_.size ());
      int shared = 0;
      for (std::size_t i = 0; i < n; ++i)
        shared += __builtin_popcountll (words_[i] & other.words_[i]);
      return shared;
    }

    void
    TensorComparator::setScene (const TensorDescriptor& scene)
    {
      const std::size_t dense_size = static_cast<std::size_t> (scene.denseSize ());
      if (dense_.size () < dense_size)
      {
        dense_.assign (dense_size, 0.0f);
        stamp_.assign (dense_size, 0u);
      }
      // A new epoch invalidates the previous scene without clearing the grid.
      if (++epoch_ == 0)
      {
        std::fill (stamp_.begin (), stamp_.end (), 0u);
        epoch_ = 1;
      }
      for (std::size_t k = 0; k < scene.bin_index.size (); ++k)
      {
        dense_[scene.bin_index[k]] = scene.bin_area[k];
        stamp_[scene.bin_index[k]] = epoch_;
      }
      scene_bins_ = scene.bin_index.size ();
    }

    void
    TensorComparator::compare (const TensorDescriptor& model, TensorMatch& match) const
    {
      double sp = 0.0, sq = 0.0, spp = 0.0, sqq = 0.0, spq = 0.0;
      int n_q = 0;
      const std::size_t limit = stamp_.size ();
      for (std::size_t k = 0; k < model.bin_index.size (); ++k)
      {
        const std::size_t bin = model.bin_index[k];
        if (bin >= limit || stamp_[bin] != epoch_)
          continue;
        const double p = model.bin_area[k], q = dense_[bin];
        ++n_q;
        sp += p;
        sq += q;
        spp += p * p;
        sqq += q * q;
        spq += p * q;
      }
      match.n_q = n_q;
      match.overlap_ratio = overlapRatio (n_q, model.bin_index.size (), scene_bins_);  // Eq. 5
      const double n = n_q;
      const double var_p = n * spp - sp * sp, var_q = n * sqq - sq * sq;
      if (n_q < 2 || var_p <= 0.0 || var_q <= 0.0)
      {
        match.correlation = 0.0f;
        return;
      }
      match.correlation = static_cast<float> ((n * spq - sp * sq) / std::sqrt (var_p * var_q));  // Eq. 6
    }

    namespace
    {
      using Frame = Eigen::Matrix<float, 3, 3, Eigen::RowMajor>;

      /** Eq. 7-8 from the two frames (rows: x, y, z axes) and origins. */
      Eigen::Matrix4f
      transformFromFrames (const Frame& b_m, const Eigen::Vector3f& o_m, const Frame& b_s, const Eigen::Vector3f& o_s)
      {
        const Eigen::Matrix3f r = b_m.transpose () * b_s;
        Eigen::Matrix4f t = Eigen::Matrix4f::Identity ();
        t.topLeftCorner<3, 3> () = r;
        t.topRightCorner<3, 1> () = o_m - r * o_s;
        return t;
      }
    }

    Eigen::Matrix4f
    transformFromTensorPair (const TensorDescriptor& model, const TensorDescriptor& scene)
    {
      return transformFromFrames (Eigen::Map<const Frame> (model.rf), model.getVector3fMap (), Eigen::Map<const Frame> (scene.rf),
                                  scene.getVector3fMap ());
    }

    Eigen::Matrix4f
    transformFromTensorMatch (const TensorMatch& match, const pcl::PointCloud<TensorDescriptor>& model_tensors,
                              const pcl::PointCloud<TensorDescriptor>& scene_tensors)
    {
      const TensorDescriptor& model = model_tensors[match.model];
      const TensorDescriptor& scene = scene_tensors[match.scene];
      Frame b_s = Eigen::Map<const Frame> (scene.rf);
      // The swapped pair order turns the frame half a turn about its z axis (flipPairOrder()).
      if (match.scene_flipped)
        b_s.topRows<2> () *= -1.0f;
      return transformFromFrames (Eigen::Map<const Frame> (model.rf), model.getVector3fMap (), b_s, scene.getVector3fMap ());
    }
  }
}
