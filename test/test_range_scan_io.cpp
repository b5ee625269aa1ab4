#include "test_utils.h"

#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/range_scan_io.h>

#include <cstdio>
#include <fstream>

namespace
{
  std::string
  writeTemp (const std::string& name, const std::string& text)
  {
    const std::string path = ::testing::TempDir () + name;
    std::ofstream (path) << text;
    return path;
  }
}

TEST (RangeScanIO, StanfordScansLoadAsOrganizedGridsWithHonestDenseFlag)
{
  for (const auto& name : pcl_tensor_test::bunnyScanNames ())
  {
    PCL_TENSOR_REQUIRE_SHARED_DATA (path, name);
    const pcl::io::RangeScan scan = pcl::io::loadRangeScan (path);
    EXPECT_TRUE (scan.cloud->isOrganized ()) << name;
    EXPECT_FALSE (scan.cloud->is_dense) << name << ": PCL marks it dense, but it has NaN cells";
    std::size_t finite = 0;
    for (const auto& p : *scan.cloud)
      finite += pcl::isXYZFinite (p);
    EXPECT_EQ (finite, scan.finite_points) << name;
    EXPECT_GT (scan.finite_points, 10000u) << name;
    // The file carries no pose, but its grid is a pushbroom's (GridSensorFit).
    EXPECT_EQ (scan.viewpoint.model, pcl::ScanViewpoint::Model::pushbroom) << name;
  }
}

TEST (RangeScanIO, Bun045HasTheDocumentedGrid)
{
  PCL_TENSOR_REQUIRE_SHARED_DATA (path, "stanford/bunny/bun045.ply");
  const pcl::io::RangeScan scan = pcl::io::loadRangeScan (path);
  EXPECT_EQ (scan.cloud->width, 512u);
  EXPECT_EQ (scan.cloud->height, 400u);
  EXPECT_EQ (scan.finite_points, 40097u);  // data/README.md
}

TEST (RangeScanIO, PcdSensorPoseBecomesThePerspectiveViewpoint)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < 5; ++i)
    cloud.push_back (pcl::PointXYZ (static_cast<float> (i), static_cast<float> (i * i), 1.0f));
  cloud.push_back (pcl::PointXYZ (std::nanf (""), 0, 0));
  cloud.is_dense = true;  // the lie PCL tells about Stanford scans; the loader must not trust it
  cloud.sensor_origin_ = Eigen::Vector4f (1, 2, 3, 0);
  const std::string path = ::testing::TempDir () + "pose.pcd";
  pcl::io::savePCDFileBinary (path, cloud);
  const pcl::io::RangeScan scan = pcl::io::loadRangeScan (path);
  EXPECT_EQ (scan.cloud->size (), 5u) << "the NaN point of an unorganized cloud is dropped";
  EXPECT_TRUE (scan.cloud->is_dense);
  EXPECT_EQ (scan.viewpoint.model, pcl::ScanViewpoint::Model::perspective);
  EXPECT_TRUE (scan.viewpoint.sensor_pose.translation ().isApprox (Eigen::Vector3d (1, 2, 3)));
}

TEST (RangeScanIO, BadFilesThrowDocumentedExceptions)
{
  EXPECT_THROW (pcl::io::loadRangeScan ("/nonexistent/scan.ply"), pcl::IOException);
  EXPECT_THROW (pcl::io::loadRangeScan (writeTemp ("scan.xyz", "1 2 3\n")), pcl::IOException);
  EXPECT_THROW (pcl::io::loadRangeScan (writeTemp ("garbage.ply", "this is not a ply file\n\x01\x02")), pcl::IOException);
  const std::string faces_only = "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                                 "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n3 0 1 2\n";
  EXPECT_THROW (pcl::io::loadRangeScan (writeTemp ("faces_only.ply", faces_only)), pcl::PCLException);
}

TEST (RangeScanIO, TooFewFinitePointsThrowInvalidScan)
{
  const std::string two = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                          "property float z\nend_header\n0 0 0\n1 0 0\nnan nan nan\n";
  EXPECT_THROW (pcl::io::loadRangeScan (writeTemp ("two.ply", two)), pcl::InvalidScanException);
  const std::string nan = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                          "property float z\nend_header\nnan nan nan\nnan nan nan\n";
  EXPECT_THROW (pcl::io::loadRangeScan (writeTemp ("nan.ply", nan)), pcl::InvalidScanException);
  pcl::PointCloud<pcl::PointXYZ> empty;
  const std::string path = ::testing::TempDir () + "empty.pcd";
  pcl::io::savePCDFileASCII (path, empty);
  EXPECT_THROW (pcl::io::loadRangeScan (path), pcl::PCLException);
}

TEST (RangeScanIO, UpdateDenseFlagCountsFinitePoints)
{
  pcl::PointCloud<pcl::PointXYZ> cloud (2, 2);
  cloud.at (0, 0) = pcl::PointXYZ (0, 0, 0);
  cloud.at (1, 0) = pcl::PointXYZ (std::nanf (""), 0, 0);
  cloud.at (0, 1) = pcl::PointXYZ (1, 1, 1);
  cloud.at (1, 1) = pcl::PointXYZ (0, std::numeric_limits<float>::infinity (), 0);
  cloud.is_dense = true;
  EXPECT_EQ (pcl::io::updateDenseFlag (cloud), 2u);
  EXPECT_FALSE (cloud.is_dense);
}
