/*
 * libFuzzer target: range image -> M_i -> M'_i -> tensors (Section 2) on small fuzzed range images.
 * Byte 0 gives the grid width (3..18), byte 1 the face target; then one byte of depth per cell (0 is
 * a hole), for 2 to 18 rows. Every input either gives tensors or throws pcl::InvalidScanException.
 */
#include <pcl/common/object_dimensions.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/registration/tensor_registration.h>
#include <pcl/surface/scan_preparation.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  if (size < 2)
    return 0;
  const std::size_t width = 3 + data[0] % 16;
  const std::size_t cells = size - 2;
  const std::size_t height = std::min<std::size_t> (cells / width, 18);
  if (height < 2)
    return 0;  // one row is not a grid: PCL calls a cloud of height 1 unorganized
  pcl::PointCloud<pcl::PointXYZ> cloud (static_cast<std::uint32_t> (width), static_cast<std::uint32_t> (height));
  for (std::size_t r = 0; r < height; ++r)
    for (std::size_t c = 0; c < width; ++c)
    {
      const std::uint8_t depth = data[2 + r * width + c];
      cloud[r * width + c] = depth == 0 ? pcl::PointXYZ (NAN, NAN, NAN)
                                   : pcl::PointXYZ (0.01f * c, 0.01f * r, 1.0f + 0.002f * depth);
    }
  cloud.is_dense = false;
  pcl::registration::TensorRegistrationParams params;
  params.preparation.target_faces = 4 + data[1] % 64;
  try
  {
    const pcl::PreparedScan scan = pcl::prepareScan (cloud, pcl::ScanViewpoint::fromPositiveZ (), params.preparation);
    const pcl::ObjectDimensions dims = pcl::computeObjectDimensions<pcl::PointNormal> ({scan.fine.cloud.get ()});
    const auto tensors = pcl::registration::computeViewTensors (scan, dims, params);
    for (const auto& t : *tensors)
      for (float a : t.bin_area)
        if (!std::isfinite (a) || a < 0.0f)
          std::abort ();  // a tensor holds surface areas
  }
  catch (const pcl::InvalidScanException&)
  {
  }
  return 0;
}
