/*
 * pcl_tensor: savePointCloudPLY's files read back exactly, organized ones as organized, with our reader
 * and with PCL's.
 */
#include "test_utils.h"

#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/io/ply_io.h>
#include <pcl/io/point_cloud_ply.h>
#include <pcl/io/range_scan_io.h>

#include <cmath>
#include <limits>

namespace
{
  pcl::PointCloud<pcl::PointXYZ>
  grid (std::uint32_t width, std::uint32_t height)
  {
    pcl::PointCloud<pcl::PointXYZ> cloud (width, height);
    for (std::size_t i = 0; i < cloud.size (); ++i)
      cloud[i] = pcl::PointXYZ (0.001f * i, std::sin (0.1f * i), 1.0f / (i + 3.0f));
    cloud[1].x = cloud[1].y = cloud[1].z = std::numeric_limits<float>::quiet_NaN ();
    cloud.is_dense = false;
    return cloud;
  }

  void
  expectSamePoints (const pcl::PointCloud<pcl::PointXYZ>& a, const pcl::PointCloud<pcl::PointXYZ>& b)
  {
    ASSERT_EQ (a.size (), b.size ());
    for (std::size_t i = 0; i < a.size (); ++i)
    {
      ASSERT_EQ (pcl::isFinite (a[i]), pcl::isFinite (b[i])) << i;
      if (pcl::isFinite (a[i]))
      {
        ASSERT_EQ (a[i].getVector3fMap (), b[i].getVector3fMap ()) << i;
      }
    }
  }
}

TEST (PointCloudPLY, AnOrganizedCloudReadsBackOrganized)
{
  const auto cloud = grid (7, 5);
  const std::string path = ::testing::TempDir () + "organized_cloud.ply";
  pcl::io::savePointCloudPLY (path, cloud);
  const pcl::io::RangeScan scan = pcl::io::loadRangeScan (path);
  EXPECT_EQ (scan.cloud->width, 7u);
  EXPECT_EQ (scan.cloud->height, 5u);
  expectSamePoints (*scan.cloud, cloud);
}

TEST (PointCloudPLY, PclReadsItBack)
{
  auto cloud = grid (40, 1);
  cloud[1] = pcl::PointXYZ (1.0f, 2.0f, 3.0f);  // PCL's reader keeps no NaN vertex apart
  const std::string path = ::testing::TempDir () + "cloud.ply";
  pcl::io::savePointCloudPLY (path, cloud);
  pcl::PointCloud<pcl::PointXYZ> read;
  ASSERT_EQ (pcl::io::loadPLYFile (path, read), 0);
  expectSamePoints (read, cloud);
}

TEST (PointCloudPLY, AnUnwritablePathThrows)
{
  EXPECT_THROW (pcl::io::savePointCloudPLY ("/nonexistent/dir/cloud.ply", grid (3, 1)), pcl::IOException);
}
