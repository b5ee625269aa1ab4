/*
 * pcl_tensor: known-answer tests of the scan noise estimate that verification's tolerances use.
 */
#include "test_utils.h"

#include <pcl/common/scan_noise.h>
#include <pcl/common/tensor_exceptions.h>

namespace
{
  /** A 150 x 150 grid of 1 mm pitch on a tilted plane, with Gaussian noise of \a sigma along its normal. */
  pcl::PointCloud<pcl::PointNormal>
  noisyPlane (double sigma, std::uint32_t seed)
  {
    std::mt19937 rng (seed);
    std::normal_distribution<double> noise (0.0, 1.0);
    const Eigen::Vector3d normal = Eigen::Vector3d (0.3, -0.2, 1.0).normalized ();
    const Eigen::Vector3d u = normal.unitOrthogonal (), v = normal.cross (u);
    pcl::PointCloud<pcl::PointNormal> cloud;
    for (int i = 0; i < 150; ++i)
      for (int j = 0; j < 150; ++j)
      {
        pcl::PointNormal p;
        p.getVector3fMap () = (1e-3 * (i * u + j * v) + sigma * noise (rng) * normal).cast<float> ();
        cloud.push_back (p);
      }
    return cloud;
  }
}

TEST (ScanNoise, GaussianNoiseOnAPlaneIsRecovered)
{
  for (const double sigma : {2e-4, 5e-4, 1e-3})
    EXPECT_NEAR (pcl::estimateScanNoise (noisyPlane (sigma, 5), 3e-3), sigma, 0.15 * sigma) << "sigma " << sigma;
  EXPECT_LT (pcl::estimateScanNoise (noisyPlane (0.0, 5), 3e-3), 1e-6);
}

TEST (ScanNoise, NanPointsAreSkippedAndBadArgumentsRefused)
{
  auto cloud = noisyPlane (5e-4, 9);
  for (std::size_t i = 0; i < cloud.size (); i += 3)
    cloud[i].x = std::numeric_limits<float>::quiet_NaN ();
  EXPECT_NEAR (pcl::estimateScanNoise (cloud, 3e-3), 5e-4, 0.15 * 5e-4);
  EXPECT_EQ (pcl::estimateScanNoise (pcl::PointCloud<pcl::PointNormal> (), 3e-3), 0.0);
  EXPECT_THROW (pcl::estimateScanNoise (cloud, 0.0), pcl::BadArgumentException);
  EXPECT_THROW (pcl::estimateScanNoise (cloud, std::numeric_limits<double>::quiet_NaN ()), pcl::BadArgumentException);
  EXPECT_THROW (pcl::estimateScanNoise (cloud, 3e-3, 0), pcl::BadArgumentException);
}
