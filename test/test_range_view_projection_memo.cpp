/*
 * pcl_tensor: tests of the per-view memo of z-buffers that verification shares between pairs.
 */
#include "test_utils.h"

#include <pcl/surface/range_view_projection_memo.h>

#include <atomic>
#include <stdexcept>
#include <thread>

namespace
{
  /** A 2 x 2 square of two triangles at z = 0, seen from +z: the least a z-buffer can be made of. */
  std::shared_ptr<const pcl::PreparedScan>
  square ()
  {
    auto scan = std::make_shared<pcl::PreparedScan> ();
    for (const auto& xy : {Eigen::Vector2f (-1, -1), Eigen::Vector2f (1, -1), Eigen::Vector2f (1, 1), Eigen::Vector2f (-1, 1)})
    {
      pcl::PointNormal p;
      p.x = xy.x ();
      p.y = xy.y ();
      p.z = 0.0f;
      scan->fine.cloud->push_back (p);
    }
    pcl::Vertices a, b;
    a.vertices = {0, 1, 2};
    b.vertices = {0, 2, 3};
    scan->fine.polygons = {a, b};
    scan->fine.viewpoint = pcl::ScanViewpoint::fromPositiveZ ();
    scan->resolution = 0.5;
    return scan;
  }

  /** A maker that counts its calls. */
  std::function<pcl::RangeViewProjectionMemo::Projection ()>
  counting (const std::shared_ptr<const pcl::PreparedScan>& scan, std::atomic<int>& calls)
  {
    return [scan, &calls] {
      ++calls;
      return std::make_shared<const pcl::RangeViewProjection> (scan->fine, 3.0, 2.0, 16u << 20, scan->resolution);
    };
  }
}

// One build per scan and setting: the same projection for every later ask, another for another
// setting or another scan.
TEST (RangeViewProjectionMemo, BuildsOncePerScanAndSetting)
{
  pcl::RangeViewProjectionMemo memo;
  const auto scan = square ();
  std::atomic<int> calls{0};
  const auto first = memo.get (scan, -1, counting (scan, calls));
  ASSERT_TRUE (first);
  EXPECT_EQ (memo.get (scan, -1, counting (scan, calls)), first);
  EXPECT_EQ (calls, 1);
  const auto other_setting = memo.get (scan, 4, counting (scan, calls));
  EXPECT_NE (other_setting, first);
  EXPECT_EQ (calls, 2);
  const auto other_scan = square ();
  EXPECT_NE (memo.get (other_scan, -1, counting (other_scan, calls)), first);
  EXPECT_EQ (calls, 3);
  // What is kept is a real z-buffer of the square: the surface 0.1 below a point above it.
  pcl::RangeViewProjection::Sample s;
  ASSERT_TRUE (first->sample (Eigen::Vector3f (0.2f, 0.3f, 0.1f), s));
  EXPECT_NEAR (s.distance, 0.1, 1e-6);
}

// Pairs on several threads asking for the same view's z-buffer at once: it is built once and all
// get that one.
TEST (RangeViewProjectionMemo, ConcurrentAsksBuildOnce)
{
  pcl::RangeViewProjectionMemo memo;
  const auto scan = square ();
  std::atomic<int> calls{0};
  std::vector<pcl::RangeViewProjectionMemo::Projection> got (8);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < got.size (); ++t)
    threads.emplace_back ([&, t] { got[t] = memo.get (scan, -1, counting (scan, calls)); });
  for (auto& t : threads)
    t.join ();
  EXPECT_EQ (calls, 1);
  for (const auto& p : got)
    EXPECT_EQ (p, got.front ());
}

// A build that throws leaves nothing behind: the next ask builds again.
TEST (RangeViewProjectionMemo, AFailedBuildKeepsNothing)
{
  pcl::RangeViewProjectionMemo memo;
  const auto scan = square ();
  EXPECT_THROW (memo.get (scan, -1, [] () -> pcl::RangeViewProjectionMemo::Projection { throw std::runtime_error ("no"); }),
                std::runtime_error);
  std::atomic<int> calls{0};
  EXPECT_TRUE (memo.get (scan, -1, counting (scan, calls)));
  EXPECT_EQ (calls, 1);
}

// clear() drops what is kept; a projection still in use lives on with its user, and the next ask
// builds a new one.
TEST (RangeViewProjectionMemo, ClearDropsWhatIsKept)
{
  pcl::RangeViewProjectionMemo memo;
  const auto scan = square ();
  std::atomic<int> calls{0};
  EXPECT_TRUE (memo.empty ());
  const auto held = memo.get (scan, -1, counting (scan, calls));
  EXPECT_FALSE (memo.empty ());
  memo.clear ();
  EXPECT_TRUE (memo.empty ());
  pcl::RangeViewProjection::Sample s;
  EXPECT_TRUE (held->sample (Eigen::Vector3f (0.0f, 0.0f, 0.2f), s));
  EXPECT_NE (memo.get (scan, -1, counting (scan, calls)), held);
  EXPECT_EQ (calls, 2);
}
