/*
 * pcl_tensor: the PLY range scan reader gives what pcl::PLYReader gives, ASCII and binary, reads the
 * odd headers on which PCL's reader aborts, and refuses malformed files with an exception.
 */
#include "test_utils.h"

#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/console/print.h>
#include <pcl/io/ply_io.h>
#include <pcl/io/range_ply.h>

#include <algorithm>
#include <cstring>
#include <limits>

namespace
{
  const std::string kGridHeader = "ply\nformat ascii 1.0\nobj_info num_cols 2\nobj_info num_rows 2\n"
                                  "element vertex 3\nproperty float x\nproperty float confidence\nproperty float y\n"
                                  "property float z\nelement range_grid 4\nproperty list uchar int vertex_indices\nend_header\n";

  /** Packed binary PLY values in a chosen byte order. */
  class Packed
  {
    public:
      explicit Packed (bool big_endian) : big_endian_ (big_endian) {}

      template <typename T> Packed&
      operator<< (T value)
      {
        char bytes[sizeof (T)];
        std::memcpy (bytes, &value, sizeof (T));
        if (big_endian_)  // the test machine is little-endian (x86-64, arm64)
          std::reverse (bytes, bytes + sizeof (T));
        data_.append (bytes, sizeof (T));
        return *this;
      }

      const std::string&
      str () const { return data_; }

    private:
      bool big_endian_;
      std::string data_;
  };

  /** A 3 x 2 grid of which cell 1 is empty, as PCL's writers keep it: organized, NaN in the hole. */
  pcl::PointCloud<pcl::PointXYZ>
  smallOrganizedCloud ()
  {
    pcl::PointCloud<pcl::PointXYZ> cloud (3, 2);
    for (std::size_t i = 0; i < cloud.size (); ++i)
      cloud[i] = pcl::PointXYZ (0.125f * i, -1.5f + i, 2.0f + 0.001f * i);
    const float nan = std::numeric_limits<float>::quiet_NaN ();
    cloud[1] = pcl::PointXYZ (nan, nan, nan);
    cloud.is_dense = false;
    return cloud;
  }
}

TEST (RangePLY, ReadsWhatPCLWritesLikePCLReader)
{
  pcl::console::setVerbosityLevel (pcl::console::L_ERROR);  // PCL warns of camera properties it skips
  pcl::PointCloud<pcl::PointXYZ> unorganized;
  for (int i = 0; i < 7; ++i)
    unorganized.push_back (pcl::PointXYZ (1.0f / (i + 1), 3.0f * i, -0.5f * i));
  const pcl::PointCloud<pcl::PointXYZ> organized = smallOrganizedCloud ();
  pcl::PointCloud<pcl::PointXYZ> dense = organized;
  dense[1] = pcl::PointXYZ (9.0f, 9.0f, 9.0f);
  dense.is_dense = true;
  const std::pair<const char*, const pcl::PointCloud<pcl::PointXYZ>*> clouds[] = {
    {"unorganized", &unorganized}, {"organized", &organized}, {"dense", &dense}};
  for (const auto& [name, cloud] : clouds)
    for (const bool binary : {true, false})
      for (const bool camera : {true, false})
      {
        const std::string path = ::testing::TempDir () + name + (binary ? "_bin" : "_ascii") + (camera ? "_cam.ply" : ".ply");
        SCOPED_TRACE (path);
        ASSERT_EQ (pcl::PLYWriter ().write (path, *cloud, binary, camera), 0);
        pcl::PointCloud<pcl::PointXYZ> ours, reference;
        pcl::io::readRangePLY (path, ours);
        ASSERT_GE (pcl::PLYReader ().read (path, reference), 0);
        pcl_tensor_test::expectIdenticalPoints (reference, ours);
        EXPECT_EQ (ours.height, cloud->height) << "the grid survives the round trip";
        EXPECT_EQ (ours.is_dense, cloud->is_dense);
      }
}

TEST (RangePLY, ReadsBigEndianMixedTypesAndSkipsLists)
{
  // A face element before the vertices, a list inside the vertex element, x, y, z of three types.
  const std::string header = "ply\nformat binary_big_endian 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
                             "element vertex 2\nproperty double x\nproperty list ushort float tags\nproperty short y\n"
                             "property uchar z\nend_header\n";
  Packed body (true);
  body << std::uint8_t (3) << std::int32_t (0) << std::int32_t (1) << std::int32_t (1);
  body << 0.25 << std::uint16_t (2) << 7.0f << 8.0f << std::int16_t (-300) << std::uint8_t (200);
  body << -1e3 << std::uint16_t (0) << std::int16_t (5) << std::uint8_t (0);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  pcl::io::readRangePLY (pcl_tensor_test::writeTempFile ("big_endian.ply", header + body.str ()), cloud);
  ASSERT_EQ (cloud.size (), 2u);
  EXPECT_EQ (cloud.height, 1u);
  EXPECT_EQ (cloud[0].x, 0.25f);
  EXPECT_EQ (cloud[0].y, -300.0f);
  EXPECT_EQ (cloud[0].z, 200.0f);
  EXPECT_EQ (cloud[1].x, -1000.0f);
  EXPECT_EQ (cloud[1].y, 5.0f);
  EXPECT_EQ (cloud[1].z, 0.0f);
}

TEST (RangePLY, ReadsBinaryRangeGrid)
{
  const std::string header = "ply\nformat binary_little_endian 1.0\nobj_info num_cols 2\nobj_info num_rows 2\n"
                             "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                             "element range_grid 4\nproperty list uchar int vertex_indices\nend_header\n";
  Packed body (false);
  for (int v = 0; v < 3; ++v)
    body << float (v) << float (10 + v) << float (20 + v);
  body << std::uint8_t (1) << std::int32_t (2) << std::uint8_t (0) << std::uint8_t (1) << std::int32_t (0)
       << std::uint8_t (2) << std::int32_t (1) << std::int32_t (0);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  pcl::io::readRangePLY (pcl_tensor_test::writeTempFile ("binary_grid.ply", header + body.str ()), cloud);
  ASSERT_EQ (cloud.width, 2u);
  ASSERT_EQ (cloud.height, 2u);
  EXPECT_FALSE (cloud.is_dense);
  EXPECT_EQ (cloud[0].z, 22.0f);
  EXPECT_FALSE (pcl::isXYZFinite (cloud[1]));
  EXPECT_EQ (cloud[2].y, 10.0f);
  EXPECT_EQ (cloud[3].x, 1.0f) << "a cell listing two vertices keeps the first";
}

TEST (RangePLY, ValuesBeyondFloatBecomeInfinite)
{
  const std::string xyz = "property double x\nproperty float y\nproperty float z\n";
  Packed big (false);
  big << 1e300 << 1.0f << 2.0f << -1e300 << 3.0f << 4.0f << 5.0 << 6.0f << 7.0f;
  const std::pair<const char*, std::string> cases[] = {
    {"ascii_beyond_float.ply", "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz + "end_header\n1e300 1 2\n-1e300 3 4\n5 6 7\n"},
    {"binary_beyond_float.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + xyz + "end_header\n" + big.str ()},
  };
  for (const auto& [name, text] : cases)
  {
    pcl::PointCloud<pcl::PointXYZ> cloud;
    pcl::io::readRangePLY (pcl_tensor_test::writeTempFile (name, text), cloud);
    ASSERT_EQ (cloud.size (), 3u) << name;
    EXPECT_EQ (cloud[0].x, std::numeric_limits<float>::infinity ()) << name;
    EXPECT_EQ (cloud[1].x, -std::numeric_limits<float>::infinity ()) << name;
    EXPECT_EQ (cloud[2].x, 5.0f) << name;
    EXPECT_FALSE (cloud.is_dense) << name;
  }
}

/** Each of these made PCL 1.13's PLYReader assert (abort the process); found by fuzz_range_scan. */
TEST (RangePLY, ReadsHeadersOnWhichPCLAborts)
{
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  Packed three (false);
  for (int v = 0; v < 3; ++v)
    three << float (v) << float (v * v) << 1.0f;
  const std::pair<const char*, std::string> cases[] = {
    {"obj_info_indented.ply", "ply\nformat binary_little_endian 1.0\n obj_info num_cols 3\nelement vertex 3\n" + xyz + "end_header\n"},
    {"obj_info_vtab.ply", "ply\nformat binary_little_endian 1.0\n\vobj_info is_mesh 0\nelement vertex 3\n" + xyz + "end_header\n"},
    {"grid_too_small.ply", "ply\nformat binary_little_endian 1.0\nobj_info num_cols 1\nobj_info num_rows 2\n"
                           "element vertex 3\n" + xyz + "end_header\n"},
  };
  for (const auto& [name, header] : cases)
  {
    pcl::PointCloud<pcl::PointXYZ> cloud;
    pcl::io::readRangePLY (pcl_tensor_test::writeTempFile (name, header + three.str ()), cloud);
    ASSERT_EQ (cloud.size (), 3u) << name;
    EXPECT_EQ (cloud.height, 1u) << name;
    EXPECT_EQ (cloud[2].y, 4.0f) << name;
  }
}

/** An element without properties holds no data, so its count says nothing; fuzz_range_scan found a
  * camera element counting 5e15 that the reader looped over until the fuzzer's timeout. */
TEST (RangePLY, SkipsElementsWithoutPropertiesWhateverTheirCount)
{
  const std::string xyz = "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n";
  for (const char* element : {"camera", "material"})
  {
    const std::string header = "ply\nformat ascii 1.0\nelement " + std::string (element) + " 5000000000000000\n" + xyz + "end_header\n";
    pcl::PointCloud<pcl::PointXYZ> cloud;
    pcl::io::readRangePLY (pcl_tensor_test::writeTempFile ("propertyless.ply", header + "1 2 3\n"), cloud);
    ASSERT_EQ (cloud.size (), 1u) << element;
    EXPECT_EQ (cloud[0].z, 3.0f) << element;
  }
}

TEST (RangePLY, ReadsGridSkippingOtherProperties)
{
  const std::string path = pcl_tensor_test::writeTempFile ("grid.ply", kGridHeader + "1 0.5 2 3\n4 0.5 5 6\n-7.25 0 8e-3 9\n1 0\n0\n1 2\n1 1\n");
  pcl::PointCloud<pcl::PointXYZ> cloud;
  pcl::io::readRangePLY (path, cloud);
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

TEST (RangePLY, ReadsMeshVerticesAsUnorganizedCloud)
{
  const std::string path = pcl_tensor_test::writeTempFile ("mesh.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                      "property float y\nproperty float z\nelement face 1\n"
                                      "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  pcl::PointCloud<pcl::PointXYZ> cloud;
  pcl::io::readRangePLY (path, cloud);
  EXPECT_EQ (cloud.size (), 3u);
  EXPECT_EQ (cloud.height, 1u);
  EXPECT_TRUE (cloud.is_dense);
  EXPECT_EQ (cloud[1].x, 1.0f);
}

TEST (RangePLY, RefusesMalformedFiles)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  const std::pair<const char*, std::string> cases[] = {
    {"truncated.ply", kGridHeader + "1 0.5 2 3\n4 0.5 5 6\n-7 0 8 9\n1 0\n0\n"},
    {"bad_number.ply", kGridHeader + "1 0.5 2 3\n4 0.5 five 6\n-7 0 8 9\n1 0\n0\n1 2\n1 1\n"},
    {"bad_index.ply", kGridHeader + "1 0.5 2 3\n4 0.5 5 6\n-7 0 8 9\n1 0\n0\n1 3\n1 1\n"},
    {"huge_count.ply", "ply\nformat ascii 1.0\nelement vertex 99999999999\nproperty float x\nproperty float y\n"
                       "property float z\nend_header\n1 2 3\n"},
    {"no_xyz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n"},
    {"not_ply.ply", "plyx\nformat ascii 1.0\nend_header\n"},
    {"no_end_header.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"},
    {"no_format.ply", "ply\nelement vertex 0\nend_header\n"},
    {"version_2.ply", "ply\nformat ascii 2.0\nend_header\n"},
    {"unknown_format.ply", "ply\nformat binary_middle_endian 1.0\nend_header\n"},
    {"unknown_type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n"},
    {"float_list_length.ply", "ply\nformat ascii 1.0\nelement face 1\nproperty list float int v\nend_header\n"},
    {"orphan_property.ply", "ply\nformat ascii 1.0\nproperty float x\nend_header\n"},
    {"two_vertex_elements.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                "property float z\nelement vertex 1\nproperty float x\nend_header\n1 2 3\n4\n"},
    {"binary_truncated.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                             "property float z\nend_header\n" + std::string (20, '\0')},
    {"binary_huge_count.ply", "ply\nformat binary_big_endian 1.0\nelement vertex 4000000000\nproperty float x\n"
                              "property float y\nproperty float z\nend_header\n" + std::string (12, '\0')},
    {"binary_long_list.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                             "property float z\nproperty list uint uchar junk\nend_header\n" + std::string (12, '\0') + "\xff\xff\xff\x7f"},
    {"binary_float_index.ply", "ply\nformat binary_little_endian 1.0\nobj_info num_cols 1\nobj_info num_rows 2\n"
                               "element vertex 1\nproperty float x\nproperty float y\nproperty float z\nelement range_grid 2\n"
                               "property list uchar float vertex_indices\nend_header\n" + std::string (12, '\0') + "\x01" + std::string (4, '\0')},
  };
  for (const auto& [name, text] : cases)
    EXPECT_THROW (pcl::io::readRangePLY (pcl_tensor_test::writeTempFile (name, text), cloud), pcl::IOException) << name;
}

TEST (RangePLY, MatchesPCLReaderOnStanfordScans)
{
  PCL_TENSOR_REQUIRE_SHARED_DATA (bunny, "stanford/bunny");
  pcl::console::setVerbosityLevel (pcl::console::L_ERROR);  // PCL warns of the face lists it skips
  const std::string dragon = pcl_tensor_test::sharedDataPath ("stanford/dragon_stand");
  const std::vector<std::string> files = {bunny + "/bun000.ply", bunny + "/bun045.ply", bunny + "/top2.ply",
                                          bunny + "/bun_zipper_res3.ply", dragon + "/dragonStandRight_0.ply"};
  for (const auto& file : files)
  {
    SCOPED_TRACE (file);
    pcl::PointCloud<pcl::PointXYZ> fast, reference;
    pcl::io::readRangePLY (file, fast);
    ASSERT_GE (pcl::PLYReader ().read (file, reference), 0);
    pcl_tensor_test::expectIdenticalPoints (reference, fast);
  }
}
