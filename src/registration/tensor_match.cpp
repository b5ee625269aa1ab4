/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/registration/tensor_match.h>

#include <cmath>

namespace pcl
{
  namespace registration
  {
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
      const double n_m = static_cast<double> (model.bin_index.size ()), n_s = static_cast<double> (scene_bins_);
      const double union_bins = n_m + n_s - n_q;
      match.overlap_ratio = union_bins > 0.0 ? static_cast<float> (n_q / union_bins) : 0.0f;  // Eq. 5
      const double n = n_q;
      const double var_p = n * spp - sp * sp, var_q = n * sqq - sq * sq;
      if (n_q < 2 || var_p <= 0.0 || var_q <= 0.0)
      {
        match.correlation = 0.0f;
        return;
      }
      match.correlation = static_cast<float> ((n * spq - sp * sq) / std::sqrt (var_p * var_q));  // Eq. 6
    }

    Eigen::Matrix4f
    transformFromTensorPair (const TensorDescriptor& model, const TensorDescriptor& scene)
    {
      const Eigen::Map<const Eigen::Matrix<float, 3, 3, Eigen::RowMajor>> b_m (model.rf), b_s (scene.rf);
      const Eigen::Matrix3f r = b_m.transpose () * b_s;
      Eigen::Matrix4f t = Eigen::Matrix4f::Identity ();
      t.topLeftCorner<3, 3> () = r;
      t.topRightCorner<3, 1> () = model.getVector3fMap () - r * scene.getVector3fMap ();
      return t;
    }
  }
}
