/*
 * pcl_tensor: specks of a range image, on images of planes whose specks are placed by construction.
 */
#include <pcl/surface/speck_removal.h>
#include <pcl/surface/scan_preparation.h>
#include <pcl/common/tensor_exceptions.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
  constexpr int kWidth = 60, kHeight = 50;

  /** A perspective range image from the origin (looking along +z, 0.01 rad per pixel) of the plane n.p = d. */
  pcl::PointCloud<pcl::PointXYZ>
  planeImage (const Eigen::Vector3d& n, double d)
  {
    pcl::PointCloud<pcl::PointXYZ> cloud (kWidth, kHeight);
    for (int r = 0; r < kHeight; ++r)
      for (int c = 0; c < kWidth; ++c)
      {
        const Eigen::Vector3d ray (0.01 * (c - kWidth / 2), 0.01 * (r - kHeight / 2), 1.0);
        cloud.at (c, r).getVector3fMap () = (ray * d / n.dot (ray)).cast<float> ();
      }
    return cloud;
  }

  /** Move pixel (r, c) \a fraction of its range toward the sensor at the origin. */
  void
  pullForward (pcl::PointCloud<pcl::PointXYZ>& cloud, int r, int c, double fraction)
  {
    cloud.at (c, r).getVector3fMap () *= static_cast<float> (1.0 - fraction);
  }

  std::size_t
  count (const std::vector<bool>& flags)
  {
    return static_cast<std::size_t> (std::count (flags.begin (), flags.end (), true));
  }

  const pcl::ScanViewpoint kSensor = pcl::ScanViewpoint::lookingAt (Eigen::Vector3d::Zero (), Eigen::Vector3d::UnitZ ());
}

TEST (SpeckRemoval, SpecksInFrontOfAPlaneAreFoundAndNothingElse)
{
  pcl::PointCloud<pcl::PointXYZ> cloud = planeImage (Eigen::Vector3d::UnitZ (), 10.0);
  pullForward (cloud, 10, 10, 0.2);                       // one pixel
  for (int c = 30; c < 33; ++c)                           // three in a row, moved alike
    pullForward (cloud, 25, c, 0.05);
  const auto speck = pcl::speckPixels (cloud, kSensor, 9, 3.0);
  ASSERT_EQ (speck.size (), cloud.size ());
  for (int r = 0; r < kHeight; ++r)
    for (int c = 0; c < kWidth; ++c)
      EXPECT_EQ (speck[r * kWidth + c], (r == 10 && c == 10) || (r == 25 && c >= 30 && c < 33)) << r << ", " << c;
}

// A group beside an empty pixel may be a part of the object that dropout or a hole cut off.
TEST (SpeckRemoval, PitsLargeGroupsAndGroupsBesideEmptyPixelsAreNotSpecks)
{
  pcl::PointCloud<pcl::PointXYZ> cloud = planeImage (Eigen::Vector3d::UnitZ (), 10.0);
  pullForward (cloud, 10, 10, -0.2);                      // a pit: behind the plane
  for (int r = 20; r < 24; ++r)                           // a 4 x 4 block in front: 16 > 9 pixels
    for (int c = 20; c < 24; ++c)
      pullForward (cloud, r, c, 0.2);
  const float nan = std::numeric_limits<float>::quiet_NaN ();
  for (int r = 35; r < 40; ++r)                           // a lone pixel in an empty window
    for (int c = 40; c < 45; ++c)
      if (r != 37 || c != 42)
        cloud.at (c, r).x = cloud.at (c, r).y = cloud.at (c, r).z = nan;
  pullForward (cloud, 30, 50, 0.2);                       // in front, but beside a hole
  cloud.at (51, 30).x = cloud.at (51, 30).y = cloud.at (51, 30).z = nan;
  pullForward (cloud, 0, 20, 0.2);                        // in front, on the image's edge
  cloud.is_dense = false;
  EXPECT_EQ (count (pcl::speckPixels (cloud, kSensor, 9, 3.0)), 0u);
  // The same block is a speck when the limit admits it.
  EXPECT_EQ (count (pcl::speckPixels (cloud, kSensor, 16, 3.0)), 16u);
}

TEST (SpeckRemoval, AGrazingPlaneHasNoSpeck)
{
  // Tilted 85 degrees from the line of sight: neighbouring pixels lie several spacings apart in depth
  // along the tilt, but one is nearer and the other farther.
  const double tilt = 85.0 * M_PI / 180.0;
  const pcl::PointCloud<pcl::PointXYZ> cloud = planeImage (Eigen::Vector3d (0.0, std::sin (tilt), std::cos (tilt)), 1.0);
  EXPECT_EQ (count (pcl::speckPixels (cloud, kSensor, 9, 3.0)), 0u);
}

TEST (SpeckRemoval, RemovalEmptiesThePixelsAndKeepsTheGrid)
{
  pcl::PointCloud<pcl::PointXYZ> cloud = planeImage (Eigen::Vector3d::UnitZ (), 10.0);
  pullForward (cloud, 5, 7, 0.3);
  ASSERT_TRUE (cloud.is_dense);
  EXPECT_EQ (pcl::removeSpecks (cloud, kSensor, 9, 3.0), 1u);
  EXPECT_FALSE (cloud.is_dense);
  EXPECT_EQ (cloud.width, static_cast<std::uint32_t> (kWidth));
  EXPECT_EQ (cloud.height, static_cast<std::uint32_t> (kHeight));
  EXPECT_TRUE (std::isnan (cloud.at (7, 5).z));
  EXPECT_EQ (pcl::removeSpecks (cloud, kSensor, 9, 3.0), 0u) << "nothing left to remove";
}

TEST (SpeckRemoval, UnorganizedCloudsAndAZeroLimitKeepEverything)
{
  pcl::PointCloud<pcl::PointXYZ> cloud = planeImage (Eigen::Vector3d::UnitZ (), 10.0);
  pullForward (cloud, 5, 7, 0.3);
  EXPECT_EQ (count (pcl::speckPixels (cloud, kSensor, 0, 3.0)), 0u);
  cloud.width = static_cast<std::uint32_t> (cloud.size ());
  cloud.height = 1;
  EXPECT_EQ (count (pcl::speckPixels (cloud, kSensor, 9, 3.0)), 0u);
}

TEST (SpeckRemoval, BadParametersAreRefused)
{
  const pcl::PointCloud<pcl::PointXYZ> cloud = planeImage (Eigen::Vector3d::UnitZ (), 10.0);
  EXPECT_THROW (pcl::speckPixels (cloud, kSensor, -1, 3.0), pcl::BadArgumentException);
  EXPECT_THROW (pcl::speckPixels (cloud, kSensor, 9, 0.0), pcl::BadArgumentException);
  EXPECT_THROW (pcl::speckPixels (cloud, kSensor, 9, std::numeric_limits<double>::infinity ()), pcl::BadArgumentException);
  pcl::ScanPreparationParams params;
  params.speck_jump = -1.0;
  EXPECT_THROW (pcl::checkScanPreparationParams (params), pcl::BadArgumentException);
}

TEST (SpeckRemoval, PreparedScanKeepsNoSpeckInItsExtent)
{
  pcl::PointCloud<pcl::PointXYZ> cloud = planeImage (Eigen::Vector3d::UnitZ (), 10.0);
  pullForward (cloud, 25, 30, 0.1);                       // 1 unit (10 d_res) in front: stray fragments keep it
  const auto nearest = [] (const pcl::PreparedScan& scan) {
    float z = std::numeric_limits<float>::infinity ();
    for (const auto& p : *scan.fine.cloud)
      z = std::min (z, p.z);
    return z;
  };
  EXPECT_NEAR (nearest (pcl::prepareScan (cloud, kSensor)), 10.0f, 1e-4f);
  pcl::ScanPreparationParams keep;
  keep.speck_max_pixels = 0;
  EXPECT_NEAR (nearest (pcl::prepareScan (cloud, kSensor, keep)), 9.0f, 1e-4f) << "kept when asked";
}
