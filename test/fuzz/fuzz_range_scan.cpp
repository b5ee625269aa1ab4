/*
 * libFuzzer target: the range-image loader. The first byte picks the format (PLY or PCD); any file
 * either loads into a scan of at least 3 finite points or throws pcl::IOException or
 * pcl::InvalidScanException.
 */
#include "fuzz_file.h"

#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/io/range_scan_io.h>

#include <cstdlib>

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  if (size < 1)
    return 0;
  const std::string path = pcl_tensor_fuzz::writeInput ((data[0] & 1) ? "fuzz.pcd" : "fuzz.ply", data + 1, size - 1);
  try
  {
    const pcl::io::RangeScan scan = pcl::io::loadRangeScan (path);
    std::size_t finite = 0;
    for (const auto& p : *scan.cloud)
      finite += pcl::isXYZFinite (p) ? 1 : 0;
    if (finite != scan.finite_points || finite < 3 || scan.cloud->is_dense != (finite == scan.cloud->size ()))
      std::abort ();
  }
  catch (const pcl::IOException&)
  {
  }
  catch (const pcl::InvalidScanException&)
  {
  }
  return 0;
}
