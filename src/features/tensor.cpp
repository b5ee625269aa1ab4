/*
 * pcl_tensor: automatic pairwise registration of range images with tensors
 * (Mian, Bennamoun & Owens, IJCV 2006).
 */
#include <pcl/features/tensor.h>
#include <pcl/features/impl/tensor.hpp>

#include <algorithm>
#include <cmath>

// A short list on purpose: vertices as PointXYZ or PointNormal, normals as Normal or PointNormal.
PCL_INSTANTIATE_TensorEstimation (pcl::PointXYZ, pcl::Normal, pcl::TensorDescriptor)
PCL_INSTANTIATE_TensorEstimation (pcl::PointXYZ, pcl::PointNormal, pcl::TensorDescriptor)
PCL_INSTANTIATE_TensorEstimation (pcl::PointNormal, pcl::PointNormal, pcl::TensorDescriptor)

namespace pcl
{
  std::size_t
  countDifferingTensors (const pcl::PointCloud<TensorDescriptor>& a, const pcl::PointCloud<TensorDescriptor>& b,
                         double tolerance)
  {
    if (a.size () != b.size ())
      PCL_TENSOR_THROW (BadArgumentException, "[pcl::countDifferingTensors] " << a.size () << " and " << b.size ()
                        << " tensors: the clouds do not come from the same pairs");
    std::size_t differing = 0;
    for (std::size_t t = 0; t < a.size (); ++t)
    {
      const TensorDescriptor& p = a[t];
      const TensorDescriptor& q = b[t];
      if (p.vertex_a != q.vertex_a || p.vertex_b != q.vertex_b || p.grid_size != q.grid_size)
        PCL_TENSOR_THROW (BadArgumentException, "[pcl::countDifferingTensors] tensor " << t
                          << " has different pairs or grids in the two clouds");
      const double limit = tolerance * static_cast<double> (p.bin_size) * static_cast<double> (p.bin_size);
      std::size_t i = 0, j = 0;
      bool differ = false;
      while (!differ && (i < p.bin_index.size () || j < q.bin_index.size ()))
      {
        double va = 0.0, vb = 0.0;
        if (j >= q.bin_index.size () || (i < p.bin_index.size () && p.bin_index[i] < q.bin_index[j]))
          va = p.bin_area[i++];
        else if (i >= p.bin_index.size () || q.bin_index[j] < p.bin_index[i])
          vb = q.bin_area[j++];
        else
        {
          va = p.bin_area[i++];
          vb = q.bin_area[j++];
        }
        differ = std::abs (va - vb) > limit;
      }
      if (differ)
        ++differing;
    }
    return differing;
  }
}
