/*
 * pcl_tensor: automatic pairwise registration of range images with tensors
 * (Mian, Bennamoun & Owens, IJCV 2006).
 */
#pragma once

#include <pcl/memory.h>
#include <pcl/pcl_macros.h>
#include <pcl/point_cloud.h>
#include <pcl/point_representation.h>
#include <pcl/point_types.h>
#include <pcl/register_point_struct.h>

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <vector>

namespace pcl
{
  /** \brief Largest grid size N per axis that TensorDescriptor can hold: bin indices are
    * std::uint16_t, and 40^3 = 64,000 <= 65,535.
    * \ingroup features
    */
  constexpr int TENSOR_MAX_GRID_SIZE = 40;

  /** \brief Grid size of the dense view used by DefaultPointRepresentation<TensorDescriptor> and the
    * descriptorSize trait: the paper's 10 x 10 x 10 grid (Section 2).
    * \ingroup features
    */
  constexpr int TENSOR_DEFAULT_GRID_SIZE = 10;

  struct TensorDescriptor;

  namespace detail
  {
    namespace traits
    {
      /** \brief Dense size of a tensor with the default 10^3 grid (see DefaultPointRepresentation). */
      template <> struct descriptorSize<TensorDescriptor>
      {
        static constexpr const int value = TENSOR_DEFAULT_GRID_SIZE * TENSOR_DEFAULT_GRID_SIZE *
                                           TENSOR_DEFAULT_GRID_SIZE;
      };
    }
  }

  /** \brief One tensor of Mian et al. (2006), Section 2: the surface area of a mesh inside each bin of
    * an N x N x N grid centred on the local frame of a vertex pair, stored sparsely.
    *
    * The fixed fields are plain data and are registered with POINT_CLOUD_REGISTER_POINT_STRUCT, so a
    * PointCloud<TensorDescriptor> can be written to PCD and inspected field by field. The sparse bins
    * live in the two std::vector members (not registered; PCD/PCLPointCloud2 conversions carry the
    * fixed fields only). Copying a point or a cloud copies the bins.
    *
    * Grid and bin convention: the grid spans [-N b_s/2, N b_s/2] along each axis of the local frame;
    * bin (i_x, i_y, i_z) covers [-N b_s/2 + i b_s, -N b_s/2 + (i+1) b_s] along each axis and its
    * linear index is (i_x N + i_y) N + i_z.
    *
    * Frame: rf holds the local x, y, z axes as rows (rf[0..2] = x, rf[3..5] = y, rf[6..8] = z), as
    * pcl::SHOT352 and pcl::ReferenceFrame do; x, y, z (the point) is the origin, the midpoint of the
    * two vertices. A point p of the view maps to local coordinates rf * (p - origin).
    * \ingroup features
    */
  struct EIGEN_ALIGN16 TensorDescriptor
  {
    PCL_ADD_POINT4D;  // origin of the local frame: midpoint of the pair (Section 2)
    /** \brief Local frame, rows x, y, z (Section 2): z = normalize(n_a + n_b), x = normalize(n_a x n_b), y = z x x. */
    float rf[9] = {0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 0.f};
    /** \brief Mutual angle of the two normals, in degrees (Section 2; the key of the index table). */
    float theta_d = 0.f;
    /** \brief Bin size b_s used for this tensor (Eq. 3). */
    float bin_size = 0.f;
    /** \brief First vertex of the pair (index into the input cloud); the pair order is canonical, see TensorEstimation. */
    std::int32_t vertex_a = -1;
    /** \brief Second vertex of the pair (index into the input cloud). */
    std::int32_t vertex_b = -1;
    /** \brief Grid size N (bins per axis). */
    std::int32_t grid_size = 0;
    /** \brief 1 when the canonical pair order is not well defined (the pair is nearly symmetric about
      * the plane through the origin orthogonal to the pair axis, see TensorEstimation::setOrderAmbiguityAngle):
      * a matcher should then also try the swapped order (flipPairOrder()).
      */
    std::uint32_t order_ambiguous = 0;

    /** \brief Linear indices (i_x N + i_y) N + i_z of the non-zero bins, strictly increasing. */
    std::vector<std::uint16_t> bin_index;
    /** \brief Surface area inside each non-zero bin, same order as \a bin_index (square input units). */
    std::vector<float> bin_area;

    /** \brief An empty tensor: origin at zero, no frame, no bins. */
    TensorDescriptor () : data{0.f, 0.f, 0.f, 1.f} {}

    /** \brief Dense size N^3 of this tensor. */
    int denseSize () const { return grid_size * grid_size * grid_size; }
    /** \brief Number of non-zero bins (n_m or n_s of Eq. 5). */
    std::size_t nonZeroBins () const { return bin_index.size (); }
    /** \brief Default dense size used by the kd-tree representation: 10^3. */
    static constexpr int descriptorSize () { return detail::traits::descriptorSize<TensorDescriptor>::value; }

    PCL_MAKE_ALIGNED_OPERATOR_NEW
  };

  /** \brief Print the fixed fields and the number of non-zero bins.
    * \param[in,out] os the stream
    * \param[in] p the tensor
    * \return os */
  std::ostream&
  operator << (std::ostream& os, const TensorDescriptor& p);

  /** \brief Memory of a tensor cloud, stored sparsely (as TensorDescriptor does) and densely.
    * \ingroup features
    */
  struct TensorMemoryUsage
  {
    /** \brief Tensors counted. */
    std::size_t tensors = 0;
    /** \brief Non-zero bins over all tensors. */
    std::size_t non_zero_bins = 0;
    /** \brief Bin payload stored sparsely: non-zero bins x (2-byte index + 4-byte area). */
    std::size_t sparse_bin_bytes = 0;
    /** \brief Bin payload stored densely: N^3 x 4-byte area per tensor. */
    std::size_t dense_bin_bytes = 0;
    /** \brief Whole sparse tensors: sizeof(TensorDescriptor) (fixed fields and the two vector headers)
      * plus the sparse payload. */
    std::size_t sparse_bytes = 0;
    /** \brief Whole dense tensors: the fixed fields (sizeof(TensorDescriptor) minus the two vector
      * headers) plus the dense payload. */
    std::size_t dense_bytes = 0;

    /** \brief 1 - sparse_bytes / dense_bytes (the paper reports about 85%, Section 2). */
    double savedFraction () const
    {
      return dense_bytes == 0 ? 0.0 : 1.0 - static_cast<double> (sparse_bytes) / static_cast<double> (dense_bytes);
    }
  };

  /** \brief Memory used by \a tensors in sparse form against the dense N^3 form (Section 2, "reduces
    * the memory utilization by approximately 85%"). Heap allocator overhead of the two vectors (about
    * 16 bytes each with glibc) is not counted.
    * \param[in] tensors the tensors
    * \return the byte counts; payload sizes use the vectors' sizes, not their capacities
    * \ingroup features
    */
  TensorMemoryUsage
  computeTensorMemoryUsage (const pcl::PointCloud<TensorDescriptor>& tensors);

  /** \brief The same tensor for the swapped pair order: the frame turned by 180 degrees about z
    * (x and y negated), the bins mirrored (i_x, i_y, i_z) -> (N-1-i_x, N-1-i_y, i_z) and re-sorted,
    * and vertex_a/vertex_b swapped. Exact (the grid is symmetric about the origin).
    * \param[in] tensor a tensor
    * \return the tensor of the other pair order
    * \ingroup features
    */
  TensorDescriptor
  flipPairOrder (const TensorDescriptor& tensor);

  /** \brief Expand the sparse bins of \a tensor into a dense array of N^3 floats.
    * \param[in] tensor a tensor
    * \param[out] dense resized to N^3; zero where no surface lies
    * \ingroup features
    */
  void
  toDenseTensor (const TensorDescriptor& tensor, std::vector<float>& dense);

  /** \brief Dense representation of TensorDescriptor for PCL's kd-trees and other vector searches:
    * the N^3 bin areas, N fixed at construction (default 10, the paper's grid).
    *
    * A tensor whose grid size differs from the representation's is rejected with
    * pcl::BadArgumentException rather than silently truncated: build the representation with the
    * grid size you used (tree.setPointRepresentation(...)).
    * \ingroup features
    */
  class TensorPointRepresentation : public PointRepresentation<TensorDescriptor>
  {
    public:
      using Ptr = shared_ptr<TensorPointRepresentation>;
      using ConstPtr = shared_ptr<const TensorPointRepresentation>;

      /** \brief \param[in] grid_size N; the representation has N^3 dimensions.
        * \throw pcl::BadArgumentException when N is not in [1, TENSOR_MAX_GRID_SIZE] */
      explicit TensorPointRepresentation (int grid_size = TENSOR_DEFAULT_GRID_SIZE);

      /** \brief Grid size N this representation expects. */
      int getGridSize () const { return grid_size_; }

      /** \brief Write the dense N^3 bins of \a p to \a out.
        * \throw pcl::BadArgumentException when p.grid_size differs from getGridSize() */
      void
      copyToFloatArray (const TensorDescriptor& p, float* out) const override;

      /** \brief Whether every bin area of \a p is finite. Checked on the sparse bins: PCL 1.13's
        * isValid copies into a raw new[] buffer that leaks when copyToFloatArray throws (found by
        * LeakSanitizer), and KdTreeFLANN::setInputCloud calls isValid on every point first.
        * \throw pcl::BadArgumentException when p.grid_size differs from getGridSize() */
      bool
      isValid (const TensorDescriptor& p) const override;

    private:
      void
      requireGridSize (const TensorDescriptor& p) const;

      int grid_size_{TENSOR_DEFAULT_GRID_SIZE};
  };

  /** \brief Default (dense, 10^3 floats) representation of TensorDescriptor, so that
    * pcl::KdTreeFLANN<TensorDescriptor> works out of the box for the paper's grid. Tensors of any
    * other grid size are rejected; use TensorPointRepresentation(N) for them.
    * \ingroup features
    */
  template <>
  class DefaultPointRepresentation<TensorDescriptor> : public TensorPointRepresentation
  {
    public:
      /** \brief The dense 10^3 representation. */
      DefaultPointRepresentation () : TensorPointRepresentation (TENSOR_DEFAULT_GRID_SIZE) {}

      /** \brief A copy, as PCL's representations provide. */
      typename PointRepresentation<TensorDescriptor>::Ptr
      makeShared () const
      {
        return (typename PointRepresentation<TensorDescriptor>::Ptr (new DefaultPointRepresentation<TensorDescriptor> (*this)));
      }
  };
}

POINT_CLOUD_REGISTER_POINT_STRUCT (pcl::TensorDescriptor,
    (float, x, x)
    (float, y, y)
    (float, z, z)
    (float[9], rf, rf)
    (float, theta_d, theta_d)
    (float, bin_size, bin_size)
    (std::int32_t, vertex_a, vertex_a)
    (std::int32_t, vertex_b, vertex_b)
    (std::int32_t, grid_size, grid_size)
    (std::uint32_t, order_ambiguous, order_ambiguous)
)
