/*
 * pcl_tensor: the fast ASCII PLY range scan reader gives what pcl::PLYReader gives, and refuses
 * malformed files with an exception.
 */
#include "test_utils.h"

#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/io/ascii_range_ply.h>
#include <pcl/io/ply_io.h>

#include <cstring>
#include <fstream>

namespace
{
  std::string
  writeFile (const std::string& name, const std::string& text)
  {
    const std::string path = ::testing::TempDir () + name;
    std::ofstream (path, std::ios::binary) << text;
    return path;
  }

  /** Same size, same NaN pattern, same floats bit for bit. */
  void
  expectIdentical (const pcl::PointCloud<pcl::PointXYZ>& expected, const pcl::PointCloud<pcl::PointXYZ>& actual)
  {
    ASSERT_EQ (expected.width, actual.width);
    ASSERT_EQ (expected.height, actual.height);
    ASSERT_EQ (expected.size (), actual.size ());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < expected.size (); ++i)
    {
      const bool fe = pcl::isXYZFinite (expected[i]), fa = pcl::isXYZFinite (actual[i]);
      if (fe != fa || (fe && std::memcmp (expected[i].data, actual[i].data, 3 * sizeof (float)) != 0))
        ++differing;
    }
    EXPECT_EQ (differing, 0u);
  }

  const std::string kGridHeader = "ply\nformat ascii 1.0\nobj_info num_cols 2\nobj_info num_rows 2\n"
                                  "element vertex 3\nproperty float x\nproperty float confidence\nproperty float y\n"
                                  "property float z\nelement range_grid 4\nproperty list uchar int vertex_indices\nend_header\n";
}

TEST (AsciiRangePLY, ReadsGridSkippingOtherProperties)
{
  const std::string path = writeFile ("grid.ply", kGridHeader + "1 0.5 2 3\n4 0.5 5 6\n-7.25 0 8e-3 9\n1 0\n0\n1 2\n1 1\n");
  pcl::PointCloud<pcl::PointXYZ> cloud;
  ASSERT_TRUE (pcl::io::readAsciiRangePLY (path, cloud));
  ASSERT_EQ (cloud.width, 2u);
  ASSERT_EQ (cloud.height, 2u);
  EXPECT_FALSE (cloud.is_dense);
  EXPECT_EQ (cloud[0].x, 1.0f);
  EXPECT_EQ (cloud[0].z, 3.0f);
  EXPECT_FALSE (pcl::isXYZFinite (cloud[1]));
  EXPECT_EQ (cloud[2].x, -7.25f);
  EXPECT_EQ (cloud[2].y, 8e-3f);
  EXPECT_EQ (cloud[3].y, 5.0f);
}

TEST (AsciiRangePLY, ReadsMeshVerticesAsUnorganizedCloud)
{
  const std::string path = writeFile ("mesh.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                      "property float y\nproperty float z\nelement face 1\n"
                                      "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  pcl::PointCloud<pcl::PointXYZ> cloud;
  ASSERT_TRUE (pcl::io::readAsciiRangePLY (path, cloud));
  EXPECT_EQ (cloud.size (), 3u);
  EXPECT_EQ (cloud.height, 1u);
  EXPECT_TRUE (cloud.is_dense);
  EXPECT_EQ (cloud[1].x, 1.0f);
}

TEST (AsciiRangePLY, LeavesBinaryFilesToPCL)
{
  const std::string path = writeFile ("binary.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 1\n"
                                      "property float x\nproperty float y\nproperty float z\nend_header\n"
                                      + std::string (12, '\0'));
  pcl::PointCloud<pcl::PointXYZ> cloud;
  EXPECT_FALSE (pcl::io::readAsciiRangePLY (path, cloud));
  EXPECT_TRUE (cloud.empty ());
}

TEST (AsciiRangePLY, RefusesMalformedFiles)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  const std::pair<const char*, std::string> cases[] = {
    {"truncated.ply", kGridHeader + "1 0.5 2 3\n4 0.5 5 6\n-7 0 8 9\n1 0\n0\n"},
    {"bad_number.ply", kGridHeader + "1 0.5 2 3\n4 0.5 five 6\n-7 0 8 9\n1 0\n0\n1 2\n1 1\n"},
    {"bad_index.ply", kGridHeader + "1 0.5 2 3\n4 0.5 5 6\n-7 0 8 9\n1 0\n0\n1 3\n1 1\n"},
    {"huge_count.ply", "ply\nformat ascii 1.0\nelement vertex 99999999999\nproperty float x\nproperty float y\n"
                       "property float z\nend_header\n1 2 3\n"},
    {"no_xyz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n"},
  };
  for (const auto& [name, text] : cases)
    EXPECT_THROW (pcl::io::readAsciiRangePLY (writeFile (name, text), cloud), pcl::IOException) << name;
}

TEST (AsciiRangePLY, MatchesPCLReaderOnStanfordScans)
{
  PCL_TENSOR_REQUIRE_SHARED_DATA (bunny, "stanford/bunny");
  const std::string dragon = pcl_tensor_test::sharedDataPath ("stanford/dragon_stand");
  const std::vector<std::string> files = {bunny + "/bun000.ply", bunny + "/bun045.ply", bunny + "/top2.ply",
                                          bunny + "/bun_zipper_res3.ply", dragon + "/dragonStandRight_0.ply"};
  for (const auto& file : files)
  {
    SCOPED_TRACE (file);
    pcl::PointCloud<pcl::PointXYZ> fast, reference;
    ASSERT_TRUE (pcl::io::readAsciiRangePLY (file, fast));
    ASSERT_GE (pcl::PLYReader ().read (file, reference), 0);
    expectIdentical (reference, fast);
  }
}
