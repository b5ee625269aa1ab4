/*
 * pcl_tensor: automatic pairwise registration of range images with tensors
 * (Mian, Bennamoun & Owens, IJCV 2006).
 */
#pragma once

#include <pcl/features/tensor_descriptor.h>
#include <pcl/memory.h>
#include <pcl/point_cloud.h>

#include <cstddef>
#include <vector>

namespace pcl
{
  /** \brief The 1D index table of a view's tensors over theta_d (Section 2, last paragraph; used by the
    * matching of Section 4): bin b holds the tensors with theta_d in [b Delta, (b+1) Delta), and a
    * query for theta_d returns, without allocating, the tensors of the bins covering
    * theta_d +- Delta theta_d: bins b-1, b and b+1 (Section 7.3, Eq. 13: "multiplied by 3").
    *
    * The table stores tensor positions in the cloud it was built from, grouped by bin and increasing
    * within a bin; neighbouring bins are contiguous, so a query is one contiguous range.
    * \ingroup features
    */
  class TensorThetaIndex
  {
    public:
      using Ptr = shared_ptr<TensorThetaIndex>;
      using ConstPtr = shared_ptr<const TensorThetaIndex>;

      /** \brief A contiguous range of tensor positions. */
      struct Range
      {
        const int* first = nullptr;
        const int* last = nullptr;
        /** \brief First position. */
        const int* begin () const { return first; }
        /** \brief One past the last position. */
        const int* end () const { return last; }
        /** \brief Number of tensors in the range. */
        std::size_t size () const { return static_cast<std::size_t> (last - first); }
        /** \brief True when the range holds no tensor. */
        bool empty () const { return first == last; }
      };

      /** \brief Construct an empty table.
        * \param[in] bin_width Delta theta_d in degrees (Section 2: 5)
        * \throw pcl::BadArgumentException unless 0 < bin_width <= 180 */
      explicit TensorThetaIndex (double bin_width = 5.0);

      /** \brief Set Delta theta_d in degrees (Section 2: 5); clears the table.
        * \throw pcl::BadArgumentException unless 0 < bin_width <= 180 */
      void setBinWidth (double bin_width);
      /** \brief Delta theta_d in degrees (default 5). */
      double getBinWidth () const { return bin_width_; }

      /** \brief Index the tensors of one view by theta_d.
        * \param[in] tensors the view's tensors (theta_d in [0, 180] degrees)
        * \throw pcl::BadArgumentException when a theta_d is not finite or outside [0, 180] */
      void build (const pcl::PointCloud<TensorDescriptor>& tensors);

      /** \brief Number of bins: ceil(180 / Delta theta_d); theta_d = 180 falls into the last bin. */
      int getNumBins () const { return static_cast<int> (offsets_.size ()) - 1; }

      /** \brief Number of indexed tensors. */
      std::size_t size () const { return order_.size (); }

      /** \brief The bin of \a theta_d (degrees), clamped to [0, getNumBins() - 1]. */
      int binOf (double theta_d) const;

      /** \brief The tensors of bin \a bin (empty when out of range). */
      Range bin (int bin) const { return bins (bin, bin); }

      /** \brief The tensors of bins \a first_bin .. \a last_bin (clamped to the table). */
      Range bins (int first_bin, int last_bin) const;

      /** \brief The candidates for a tensor with angle \a theta_d: the bins covering
        * theta_d +- Delta theta_d, i.e. binOf(theta_d) - 1 .. binOf(theta_d) + 1 (Section 4).
        * \param[in] theta_d degrees
        * \return positions in the indexed cloud */
      Range candidates (double theta_d) const
      {
        const int b = binOf (theta_d);
        return bins (b - 1, b + 1);
      }

    private:
      double bin_width_{5.0};
      std::vector<int> offsets_;  // CSR over bins: tensors of bin b are order_[offsets_[b] .. offsets_[b+1])
      std::vector<int> order_;
  };
}
