/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/memory.h>
#include <pcl/surface/range_view_projection.h>
#include <pcl/surface/scan_preparation.h>

#include <functional>
#include <map>
#include <mutex>

namespace pcl
{
  /** \brief The z-buffers of one view, each built once however many pairs ask for it, on any thread.
    *
    * Free-space verification (Section 4.1) projects both views of a pair into each other's sensor. In
    * multiview registration a view is in many pairs, and its z-buffer depends on nothing but the view
    * and a setting or two, so the pairs share it: the first to ask builds it, the others wait for it.
    * \ingroup surface
    */
  class RangeViewProjectionMemo
  {
    public:
      using Ptr = shared_ptr<RangeViewProjectionMemo>;
      using ConstPtr = shared_ptr<const RangeViewProjectionMemo>;
      using Projection = shared_ptr<const RangeViewProjection>;

      /** \brief The projection of \a scan kept under \a key, made by \a make when there is none yet.
        * \param[in] scan the view's meshes (kept alive with the projection, so no other scan can take
        *            its address and be answered with its z-buffer)
        * \param[in] key what the projection depends on besides the view (the caller's settings)
        * \param[in] make builds it; an exception it throws reaches the caller and nothing is kept
        */
      Projection
      get (const shared_ptr<const PreparedScan>& scan, int key, const std::function<Projection ()>& make);

      /** \brief Drop what is kept (those still in use live on with their users); the next get() builds again. */
      void
      clear ();

      /** \brief Whether nothing is kept. */
      bool
      empty () const;

    private:
      struct Entry
      {
        shared_ptr<const PreparedScan> scan;
        Projection projection;
      };
      mutable std::mutex mutex_;
      std::map<std::pair<const PreparedScan*, int>, Entry> projections_;
  };
}
