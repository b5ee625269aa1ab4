/*
 * pcl_tensor: tests of the range_grid PLY writer (round trip through pcl::io::loadRangeScan).
 */
#include "test_utils.h"

#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/io/range_grid_ply.h>
#include <pcl/io/range_scan_io.h>
#include <pcl/simulation/example_object.h>
#include <pcl/simulation/view_set.h>

#include <cstdio>
#include <fstream>
#include <sstream>

namespace
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr
  renderedImage ()
  {
    pcl::ExampleObjectParams params;
    params.subdivisions = 4;
    const auto mesh = pcl::makeExampleObject (params);
    pcl::RangeCameraParams camera;
    camera.width = 90;
    camera.height = 70;
    pcl::ZBufferRangeRenderer renderer;
    renderer.setMesh (mesh);
    renderer.setCameraParams (camera);
    const auto target = pcl::boundingTarget (mesh);
    const auto d = pcl::makeDefaultViewDirections ();
    return renderer.render (pcl::lookAtPoses ({d[3]}, target, pcl::fittingDistance (target, camera))[0]).cloud;
  }
}

TEST (RangeGridPLY, RoundTripKeepsGridNaNsAndFloats)
{
  const auto cloud = renderedImage ();
  const std::string path = ::testing::TempDir () + "range_grid_roundtrip.ply";
  pcl::io::saveRangeGridPLY (path, *cloud);
  std::ifstream in (path);
  std::stringstream text;
  text << in.rdbuf ();
  EXPECT_NE (text.str ().find ("element range_grid " + std::to_string (90 * 70)), std::string::npos);

  const auto scan = pcl::io::loadRangeScan (path);
  ASSERT_EQ (scan.cloud->width, cloud->width);
  ASSERT_EQ (scan.cloud->height, cloud->height);
  std::size_t finite = 0;
  for (std::size_t i = 0; i < cloud->size (); ++i)
  {
    const bool f = pcl::isXYZFinite ((*cloud)[i]);
    ASSERT_EQ (f, pcl::isXYZFinite ((*scan.cloud)[i])) << "cell " << i;
    if (!f)
      continue;
    ++finite;
    EXPECT_EQ ((*cloud)[i].x, (*scan.cloud)[i].x);
    EXPECT_EQ ((*cloud)[i].y, (*scan.cloud)[i].y);
    EXPECT_EQ ((*cloud)[i].z, (*scan.cloud)[i].z);
  }
  EXPECT_EQ (scan.finite_points, finite);
  EXPECT_GT (finite, 500u);
  EXPECT_LT (finite, cloud->size ());  // the test must see NaN cells
  if (!HasFailure ())  // a failing file is kept for inspection
    std::remove (path.c_str ());
}

TEST (RangeGridPLY, RejectsUnorganizedOrEmptyClouds)
{
  pcl::PointCloud<pcl::PointXYZ> line;
  line.push_back (pcl::PointXYZ (1, 2, 3));
  EXPECT_THROW (pcl::io::saveRangeGridPLY (::testing::TempDir () + "x.ply", line), pcl::BadArgumentException);
  pcl::PointCloud<pcl::PointXYZ> empty (4, 3, pcl::PointXYZ (NAN, NAN, NAN));
  EXPECT_THROW (pcl::io::saveRangeGridPLY (::testing::TempDir () + "x.ply", empty), pcl::BadArgumentException);
  const auto cloud = renderedImage ();
  EXPECT_THROW (pcl::io::saveRangeGridPLY ("/nonexistent-dir/x.ply", *cloud), pcl::IOException);
}
