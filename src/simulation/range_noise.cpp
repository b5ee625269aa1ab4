/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/simulation/range_noise.h>
#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>

#include <cmath>

namespace pcl
{
  void
  addViewingDirectionNoise (pcl::PointCloud<pcl::PointXYZ>& cloud, const ScanViewpoint& viewpoint,
                            double sigma, std::mt19937& rng)
  {
    if (!(sigma >= 0.0) || !std::isfinite (sigma))
      PCL_TENSOR_THROW (pcl::BadArgumentException, "noise sigma must be finite and >= 0, got " << sigma);
    std::normal_distribution<double> gauss (0.0, sigma);
    for (auto& p : cloud)
    {
      if (!pcl::isXYZFinite (p))
        continue;
      const Eigen::Vector3d q = p.getVector3fMap ().cast<double> ();
      // towardSensor points back along the ray; noise is symmetric, so its sign does not matter.
      p.getVector3fMap () = (q + gauss (rng) * viewpoint.towardSensor (q)).cast<float> ();
    }
  }
}
