/*
 * pcl_tensor: automatic pairwise registration of range images with tensors
 * (Mian, Bennamoun & Owens, IJCV 2006).
 */
#include <pcl/features/tensor_index.h>
#include <pcl/common/tensor_exceptions.h>

#include <algorithm>
#include <cmath>

namespace pcl
{
  TensorThetaIndex::TensorThetaIndex (double bin_width)
  {
    setBinWidth (bin_width);
  }

  void
  TensorThetaIndex::setBinWidth (double bin_width)
  {
    if (!(bin_width > 0.0 && bin_width <= 180.0))
      PCL_TENSOR_THROW (BadArgumentException, "[pcl::TensorThetaIndex::setBinWidth] Delta theta_d = " << bin_width
                        << " is outside (0, 180]");
    bin_width_ = bin_width;
    const int num_bins = std::max (1, static_cast<int> (std::ceil (180.0 / bin_width_ - 1e-9)));
    offsets_.assign (num_bins + 1, 0);
    order_.clear ();
  }

  int
  TensorThetaIndex::binOf (double theta_d) const
  {
    const int last = getNumBins () - 1;
    if (!(theta_d > 0.0))
      return 0;
    const double b = std::floor (theta_d / bin_width_);
    return b >= last ? last : static_cast<int> (b);
  }

  void
  TensorThetaIndex::build (const pcl::PointCloud<TensorDescriptor>& tensors)
  {
    const int num_bins = getNumBins ();
    std::vector<int> bin_of (tensors.size ());
    offsets_.assign (num_bins + 1, 0);
    for (std::size_t t = 0; t < tensors.size (); ++t)
    {
      const double theta = tensors[t].theta_d;
      if (!std::isfinite (theta) || theta < 0.0 || theta > 180.0)
        PCL_TENSOR_THROW (BadArgumentException, "[pcl::TensorThetaIndex::build] tensor " << t << " has theta_d = "
                          << theta << ", outside [0, 180]");
      bin_of[t] = binOf (theta);
      ++offsets_[bin_of[t] + 1];
    }
    for (int b = 0; b < num_bins; ++b)
      offsets_[b + 1] += offsets_[b];
    order_.assign (tensors.size (), -1);
    std::vector<int> fill (offsets_.begin (), offsets_.end () - 1);
    for (std::size_t t = 0; t < tensors.size (); ++t)
      order_[fill[bin_of[t]]++] = static_cast<int> (t);
  }

  TensorThetaIndex::Range
  TensorThetaIndex::bins (int first_bin, int last_bin) const
  {
    Range r;
    const int num_bins = getNumBins ();
    first_bin = std::max (first_bin, 0);
    last_bin = std::min (last_bin, num_bins - 1);
    if (first_bin > last_bin || order_.empty ())
    {
      r.first = r.last = order_.data ();
      return r;
    }
    r.first = order_.data () + offsets_[first_bin];
    r.last = order_.data () + offsets_[last_bin + 1];
    return r;
  }
}
