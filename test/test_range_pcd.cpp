/*
 * pcl_tensor: the PCD range scan reader gives what pcl::PCDReader gives for every DATA kind, and
 * refuses with an exception the files on which PCL's reader writes past its buffers.
 */
#include "test_utils.h"

#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/range_pcd.h>

#include <limits>

namespace
{
  /** A 4 x 3 grid with two holes, extra fields around x, y and z, and a sensor pose. */
  pcl::PointCloud<pcl::PointXYZINormal>
  organizedCloud ()
  {
    pcl::PointCloud<pcl::PointXYZINormal> cloud (4, 3);
    for (std::size_t i = 0; i < cloud.size (); ++i)
    {
      cloud[i].x = 0.1f * i;
      cloud[i].y = -2.0f / (i + 1);
      cloud[i].z = 1.0f + 0.003f * i * i;
      cloud[i].intensity = static_cast<float> (i);
      cloud[i].normal_z = 1.0f;
    }
    cloud[2].x = cloud[2].y = cloud[2].z = std::numeric_limits<float>::quiet_NaN ();
    cloud[7].z = std::numeric_limits<float>::quiet_NaN ();
    cloud.is_dense = false;
    cloud.sensor_origin_ = Eigen::Vector4f (0.5f, -1.0f, 2.0f, 0.0f);
    cloud.sensor_orientation_ = Eigen::Quaternionf (Eigen::AngleAxisf (0.3f, Eigen::Vector3f (0, 1, 0)));
    return cloud;
  }
}

TEST (RangePCD, ReadsEveryDataKindLikePCLReader)
{
  const auto organized = organizedCloud ();
  pcl::PointCloud<pcl::PointXYZ> unorganized;
  for (int i = 0; i < 5; ++i)
    unorganized.push_back (pcl::PointXYZ (1.0f / (i + 1), 3.0f * i, -0.5f * i));
  for (const int kind : {0, 1, 2})  // ascii, binary, binary_compressed
  {
    const std::string tag = std::to_string (kind);
    const std::string a = ::testing::TempDir () + "organized_" + tag + ".pcd";
    const std::string b = ::testing::TempDir () + "unorganized_" + tag + ".pcd";
    pcl::PCDWriter writer;
    ASSERT_EQ (kind == 2 ? writer.writeBinaryCompressed (a, organized) : writer.write (a, organized, kind == 1), 0);
    ASSERT_EQ (kind == 2 ? writer.writeBinaryCompressed (b, unorganized) : writer.write (b, unorganized, kind == 1), 0);
    for (const std::string& path : {a, b})
    {
      SCOPED_TRACE (path);
      pcl::PointCloud<pcl::PointXYZ> ours, reference;
      pcl::io::readRangePCD (path, ours);
      ASSERT_EQ (pcl::io::loadPCDFile (path, reference), 0);
      pcl_tensor_test::expectIdenticalPoints (reference, ours);
      EXPECT_EQ (reference.sensor_origin_, ours.sensor_origin_);
      EXPECT_EQ (reference.sensor_orientation_.coeffs (), ours.sensor_orientation_.coeffs ());
      EXPECT_EQ (ours.is_dense, path == b);
    }
  }
}

TEST (RangePCD, ReadsAnyScalarTypeAndSkipsOtherFields)
{
  const std::string path = pcl_tensor_test::writeTempFile ("types.pcd", "# .PCD v0.7\nVERSION 0.7\nFIELDS rgb x normal y z\nSIZE 4 8 4 2 1\n"
                                      "TYPE U F F I U\nCOUNT 1 1 3 1 1\nWIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\n"
                                      "7 0.25 1 2 3 -300 200\n\n8 -1e3 nan 0 0 5 0\n");
  pcl::PointCloud<pcl::PointXYZ> cloud;
  pcl::io::readRangePCD (path, cloud);
  ASSERT_EQ (cloud.size (), 2u);
  EXPECT_EQ (cloud[0].x, 0.25f);
  EXPECT_EQ (cloud[0].y, -300.0f);
  EXPECT_EQ (cloud[0].z, 200.0f);
  EXPECT_EQ (cloud[1].x, -1000.0f);
  EXPECT_EQ (cloud[1].y, 5.0f);
  EXPECT_TRUE (cloud.is_dense);
  EXPECT_EQ (cloud.sensor_orientation_.w (), 1.0f) << "no VIEWPOINT: the identity, as in PCL";
}

TEST (RangePCD, RefusesMalformedFiles)
{
  const std::string head = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
  const std::string three = "WIDTH 3\nHEIGHT 1\nPOINTS 3\n";
  const std::pair<const char*, std::string> cases[] = {
    // Made PCL's ASCII reader write past its buffer (valgrind, on a fuzz_range_scan input).
    {"data_kind.pcd", head + three + "DATA asci.7\n0 0 1\n1 0 1\n0 1 1\n"},
    {"no_data.pcd", head + three},
    {"out_of_order.pcd", "FIELDS x y z\nTYPE F F F\nSIZE 4 4 4\n" + three + "DATA ascii\n0 0 1\n1 0 1\n0 1 1\n"},
    {"repeated.pcd", head + "FIELDS x y z\n" + three + "DATA ascii\n0 0 1\n1 0 1\n0 1 1\n"},
    {"unknown_entry.pcd", head + "DEPTH 3\n" + three + "DATA ascii\n0 0 1\n1 0 1\n0 1 1\n"},
    {"size_entries.pcd", "FIELDS x y z\nSIZE 4 4\nTYPE F F F\n" + three + "DATA ascii\n0 0 1\n1 0 1\n0 1 1\n"},
    {"float_of_2_bytes.pcd", "FIELDS x y z\nSIZE 4 2 4\nTYPE F F F\n" + three + "DATA ascii\n0 0 1\n1 0 1\n0 1 1\n"},
    {"count_0.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 0 1\n" + three + "DATA ascii\n0 0 1\n1 0 1\n0 1 1\n"},
    {"no_z.pcd", "FIELDS x y\nSIZE 4 4\nTYPE F F\n" + three + "DATA ascii\n0 0\n1 0\n0 1\n"},
    {"grid_not_points.pcd", head + "WIDTH 2\nHEIGHT 2\nPOINTS 3\nDATA ascii\n0 0 1\n1 0 1\n0 1 1\n"},
    {"no_width.pcd", head + "HEIGHT 1\nPOINTS 3\nDATA ascii\n0 0 1\n1 0 1\n0 1 1\n"},
    {"no_size.pcd", "FIELDS x y z\nTYPE F F F\n" + three + "DATA ascii\n0 0 1\n1 0 1\n0 1 1\n"},
    {"short_line.pcd", head + three + "DATA ascii\n0 0 1\n1 0\n0 1 1\n"},
    {"bad_number.pcd", head + three + "DATA ascii\n0 0 1\n1 0 x\n0 1 1\n"},
    {"ascii_cut.pcd", head + three + "DATA ascii\n0 0 1\n1 0 1\n"},
    {"binary_cut.pcd", head + three + "DATA binary\n" + std::string (30, '\0')},
    {"huge_points.pcd", head + "WIDTH 4000000000\nHEIGHT 1000\nPOINTS 4000000000000\nDATA binary\n" + std::string (36, '\0')},
    {"compressed_huge.pcd", head + "WIDTH 4000000000\nHEIGHT 1\nPOINTS 4000000000\nDATA binary_compressed\n"
                            + std::string ("\x04\0\0\0\0\0\0\x80", 8) + "abcd"},
    {"compressed_no_sizes.pcd", head + three + "DATA binary_compressed\n\x01\x02"},
  };
  for (const auto& [name, text] : cases)
  {
    pcl::PointCloud<pcl::PointXYZ> cloud;
    EXPECT_THROW (pcl::io::readRangePCD (pcl_tensor_test::writeTempFile (name, text), cloud), pcl::IOException) << name;
  }
}

TEST (RangePCD, NoPointsIsAnEmptyCloud)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  pcl::io::readRangePCD (pcl_tensor_test::writeTempFile ("empty_cloud.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 0\nHEIGHT 1\n"
                                                       "POINTS 0\nDATA binary\n"), cloud);
  EXPECT_TRUE (cloud.empty ());
}
