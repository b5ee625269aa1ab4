#include "test_utils.h"

#include <fstream>
#include <limits>
#include <random>

namespace pcl_tensor_test
{
  std::string
  sharedDataPath (const std::string& relative)
  {
    const std::string path = std::string (PCL_TENSOR_SHARED_DATA) + "/" + relative;
    return std::ifstream (path).good () ? path : std::string ();
  }

  const std::vector<std::string>&
  bunnyScanNames ()
  {
    static const std::vector<std::string> names = {
      "stanford/bunny/bun000.ply", "stanford/bunny/bun045.ply", "stanford/bunny/bun090.ply",
      "stanford/bunny/bun180.ply", "stanford/bunny/bun270.ply", "stanford/bunny/bun315.ply",
      "stanford/bunny/chin.ply",   "stanford/bunny/ear_back.ply", "stanford/bunny/top2.ply",
      "stanford/bunny/top3.ply"};
    return names;
  }

  pcl::PointCloud<pcl::PointXYZ>
  makeHeightField (std::uint32_t seed, int rows, int cols, double pitch, double hole_fraction)
  {
    std::mt19937 rng (seed);
    std::uniform_real_distribution<double> u (0.0, 1.0);
    struct Bump { double x, y, h, w; };
    std::vector<Bump> bumps (6);
    for (auto& b : bumps)
      b = {u (rng) * cols * pitch, u (rng) * rows * pitch, (u (rng) - 0.5) * 8 * pitch, (2 + 8 * u (rng)) * pitch};
    pcl::PointCloud<pcl::PointXYZ> cloud (static_cast<std::uint32_t> (cols), static_cast<std::uint32_t> (rows));
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c)
      {
        const double x = c * pitch, y = r * pitch;
        double z = 0.0;
        for (const auto& b : bumps)
          z += b.h * std::exp (-((x - b.x) * (x - b.x) + (y - b.y) * (y - b.y)) / (2 * b.w * b.w));
        auto& p = cloud.at (c, r);
        if (u (rng) < hole_fraction)
          p.x = p.y = p.z = std::numeric_limits<float>::quiet_NaN ();
        else
          p = pcl::PointXYZ (static_cast<float> (x), static_cast<float> (y), static_cast<float> (z));
      }
    cloud.is_dense = false;
    return cloud;
  }
}
