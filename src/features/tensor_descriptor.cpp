/*
 * pcl_tensor: automatic pairwise registration of range images with tensors
 * (Mian, Bennamoun & Owens, IJCV 2006).
 */
#include <pcl/features/tensor_descriptor.h>
#include <pcl/common/tensor_exceptions.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <ostream>
#include <sstream>

namespace pcl
{
  std::ostream&
  operator << (std::ostream& os, const TensorDescriptor& p)
  {
    os << "(" << p.x << "," << p.y << "," << p.z << " - rf:";
    for (int i = 0; i < 9; ++i)
      os << (i ? "," : "") << p.rf[i];
    os << " - theta_d: " << p.theta_d << " - bin_size: " << p.bin_size << " - vertices: " << p.vertex_a << ","
       << p.vertex_b << " - N: " << p.grid_size << " - ambiguous: " << p.order_ambiguous
       << " - non-zero bins: " << p.bin_index.size () << ")";
    return os;
  }

  TensorMemoryUsage
  computeTensorMemoryUsage (const pcl::PointCloud<TensorDescriptor>& tensors)
  {
    TensorMemoryUsage m;
    constexpr std::size_t vector_headers = sizeof (std::vector<std::uint16_t>) + sizeof (std::vector<float>);
    constexpr std::size_t fixed = sizeof (TensorDescriptor) - vector_headers;
    for (const auto& t : tensors)
    {
      ++m.tensors;
      m.non_zero_bins += t.bin_index.size ();
      const std::size_t sparse_payload = t.bin_index.size () * sizeof (std::uint16_t) + t.bin_area.size () * sizeof (float);
      const std::size_t dense_payload = static_cast<std::size_t> (t.denseSize ()) * sizeof (float);
      m.sparse_bin_bytes += sparse_payload;
      m.dense_bin_bytes += dense_payload;
      m.sparse_bytes += sizeof (TensorDescriptor) + sparse_payload;
      m.dense_bytes += fixed + dense_payload;
    }
    return m;
  }

  TensorDescriptor
  flipPairOrder (const TensorDescriptor& tensor)
  {
    TensorDescriptor out = tensor;
    for (int k = 0; k < 6; ++k)
      out.rf[k] = -tensor.rf[k];
    std::swap (out.vertex_a, out.vertex_b);
    const int n = tensor.grid_size;
    const std::size_t nz = tensor.bin_index.size ();
    std::vector<std::pair<std::uint16_t, float>> bins (nz);
    for (std::size_t k = 0; k < nz; ++k)
    {
      const int b = tensor.bin_index[k];
      const int iz = b % n;
      const int iy = (b / n) % n;
      const int ix = b / (n * n);
      bins[k] = {static_cast<std::uint16_t> (((n - 1 - ix) * n + (n - 1 - iy)) * n + iz), tensor.bin_area[k]};
    }
    std::sort (bins.begin (), bins.end (),
               [] (const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t k = 0; k < nz; ++k)
    {
      out.bin_index[k] = bins[k].first;
      out.bin_area[k] = bins[k].second;
    }
    return out;
  }

  void
  toDenseTensor (const TensorDescriptor& tensor, std::vector<float>& dense)
  {
    dense.assign (static_cast<std::size_t> (std::max (tensor.denseSize (), 0)), 0.f);
    for (std::size_t k = 0; k < tensor.bin_index.size (); ++k)
      if (tensor.bin_index[k] < dense.size ())
        dense[tensor.bin_index[k]] = tensor.bin_area[k];
  }

  TensorPointRepresentation::TensorPointRepresentation (int grid_size)
  {
    if (grid_size < 1 || grid_size > TENSOR_MAX_GRID_SIZE)
      PCL_TENSOR_THROW (BadArgumentException, "[pcl::TensorPointRepresentation] grid size N = " << grid_size
                        << " is outside [1, " << TENSOR_MAX_GRID_SIZE << "]");
    grid_size_ = grid_size;
    nr_dimensions_ = grid_size * grid_size * grid_size;
    trivial_ = false;
  }

  void
  TensorPointRepresentation::requireGridSize (const TensorDescriptor& p) const
  {
    if (p.grid_size != grid_size_)
      PCL_TENSOR_THROW (BadArgumentException, "[pcl::TensorPointRepresentation] tensor grid size " << p.grid_size
                        << " differs from the representation's " << grid_size_
                        << "; use TensorPointRepresentation(" << p.grid_size << ")");
  }

  bool
  TensorPointRepresentation::isValid (const TensorDescriptor& p) const
  {
    requireGridSize (p);
    return std::all_of (p.bin_area.begin (), p.bin_area.end (), [] (float a) { return std::isfinite (a); });
  }

  void
  TensorPointRepresentation::copyToFloatArray (const TensorDescriptor& p, float* out) const
  {
    requireGridSize (p);
    std::fill (out, out + nr_dimensions_, 0.f);
    for (std::size_t k = 0; k < p.bin_index.size (); ++k)
      out[p.bin_index[k]] = p.bin_area[k];
  }
}
