/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/surface/range_view_projection_memo.h>

namespace pcl
{
  RangeViewProjectionMemo::Projection
  RangeViewProjectionMemo::get (const shared_ptr<const PreparedScan>& scan, int key,
                                const std::function<Projection ()>& make)
  {
    // One lock per view: a second pair asking while the first builds waits rather than builds it again.
    const std::lock_guard<std::mutex> lock (mutex_);
    const std::pair<const PreparedScan*, int> id (scan.get (), key);
    auto it = projections_.find (id);
    if (it == projections_.end ())
      it = projections_.emplace (id, Entry{scan, make ()}).first;
    return it->second.projection;
  }

  void
  RangeViewProjectionMemo::clear ()
  {
    const std::lock_guard<std::mutex> lock (mutex_);
    projections_.clear ();
  }

  bool
  RangeViewProjectionMemo::empty () const
  {
    const std::lock_guard<std::mutex> lock (mutex_);
    return projections_.empty ();
  }
}
