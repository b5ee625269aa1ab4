/*
 * pcl_tensor: tests of a range view's z-buffer along its lines of sight (Curless & Levoy's per-view step).
 */
#include "test_utils.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/surface/range_scan_triangulation.h>
#include <pcl/surface/range_view_projection.h>

namespace
{
  /** A tilted plane z = 0.3 x + 0.1 y sampled on a 41 x 41 grid of pitch 1 mm, seen by an
    * orthographic sensor on the +z side (the raw Stanford convention). */
  pcl::ScanMesh
  tiltedPlane ()
  {
    pcl::PointCloud<pcl::PointXYZ> cloud (41, 41);
    for (int r = 0; r < 41; ++r)
      for (int c = 0; c < 41; ++c)
      {
        const float x = 1e-3f * (c - 20), y = 1e-3f * (r - 20);
        cloud.at (c, r) = pcl::PointXYZ (x, y, 0.3f * x + 0.1f * y);
      }
    pcl::RangeScanTriangulation triangulation;
    triangulation.setViewpoint (pcl::ScanViewpoint::fromPositiveZ ());
    pcl::ScanMesh mesh;
    triangulation.triangulate (cloud, mesh);
    return mesh;
  }
}

// Distances are exact along the lines of sight (here -z), and the interior weight is the cosine
// between the plane's normal and the line of sight.
TEST (RangeViewProjection, OrthographicPlaneDistancesAndWeights)
{
  const pcl::ScanMesh mesh = tiltedPlane ();
  const pcl::RangeViewProjection projection (mesh, 3.0);
  const double cosine = 1.0 / std::sqrt (1.0 + 0.09 + 0.01);
  for (const double x : {-0.01, 0.0, 0.0037})
    for (const double y : {-0.008, 0.0041})
      for (const double above : {0.002, -0.0015})
      {
        const Eigen::Vector3f p (x, y, 0.3 * x + 0.1 * y + above);
        pcl::RangeViewProjection::Sample s;
        ASSERT_TRUE (projection.sample (p, s));
        EXPECT_NEAR (s.distance, above, 1e-6);  // > 0 on the sensor's (+z) side
        EXPECT_NEAR (s.weight, cosine, 1e-4);
      }
  // The border's weight is 0 and rises over the ramp.
  pcl::RangeViewProjection::Sample border, inside;
  ASSERT_TRUE (projection.sample (Eigen::Vector3f (-0.01999f, 0.0f, 0.3f * -0.01999f), border));
  ASSERT_TRUE (projection.sample (Eigen::Vector3f (-0.0185f, 0.0f, 0.3f * -0.0185f), inside));
  EXPECT_LT (border.weight, 0.02);
  EXPECT_GT (inside.weight, border.weight);
  EXPECT_LT (inside.weight, cosine);
  // Lines of sight that miss the mesh are unseen.
  pcl::RangeViewProjection::Sample s;
  EXPECT_FALSE (projection.sample (Eigen::Vector3f (0.03f, 0.0f, 0.0f), s));
}

// A perspective sensor: the range difference is measured along the ray through the point.
TEST (RangeViewProjection, PerspectiveRangeDifference)
{
  pcl::ScanMesh mesh = tiltedPlane ();
  // A sensor 0.1 m above the plane's centre, looking down (its +z is the scan's -z).
  mesh.viewpoint.sensor_pose = Eigen::Translation3d (0.0, 0.0, 0.1) * Eigen::AngleAxisd (M_PI, Eigen::Vector3d::UnitX ());
  mesh.viewpoint.model = pcl::ScanViewpoint::Model::perspective;
  const pcl::RangeViewProjection projection (mesh);
  const Eigen::Vector3d sensor (0.0, 0.0, 0.1);
  for (const Eigen::Vector3d& q : {Eigen::Vector3d (0.005, -0.003, 0.0), Eigen::Vector3d (-0.012, 0.009, 0.0)})
  {
    const Eigen::Vector3d hit (q.x (), q.y (), 0.3 * q.x () + 0.1 * q.y ());
    const Eigen::Vector3d ray = (hit - sensor).normalized ();
    for (const double t : {-0.002, 0.001})
    {
      pcl::RangeViewProjection::Sample s;
      ASSERT_TRUE (projection.sample ((hit - t * ray).cast<float> (), s));
      EXPECT_NEAR (s.distance, t, 2e-6);
    }
  }
}

// A pushbroom sensor: lines of sight fan out from a line along x and stay in their plane x = const.
TEST (RangeViewProjection, PushbroomRangeDifference)
{
  pcl::ScanMesh mesh = tiltedPlane ();
  const Eigen::Vector3d axis_point (0.0, 0.02, 0.1);
  mesh.viewpoint = pcl::ScanViewpoint::pushbroom (axis_point, Eigen::Vector3d::UnitX (), Eigen::Vector3d::Zero ());
  const pcl::RangeViewProjection projection (mesh);
  for (const Eigen::Vector3d& q : {Eigen::Vector3d (0.005, -0.003, 0.0), Eigen::Vector3d (-0.012, 0.009, 0.0),
                                   Eigen::Vector3d (0.017, 0.015, 0.0)})
  {
    const Eigen::Vector3d hit (q.x (), q.y (), 0.3 * q.x () + 0.1 * q.y ());
    const Eigen::Vector3d ray = (hit - Eigen::Vector3d (hit.x (), axis_point.y (), axis_point.z ())).normalized ();
    for (const double t : {-0.002, 0.001})
    {
      pcl::RangeViewProjection::Sample s;
      ASSERT_TRUE (projection.sample ((hit - t * ray).cast<float> (), s));
      EXPECT_NEAR (s.distance, t, 2e-6);
    }
  }
  // Behind the sensor's axis nothing is seen.
  pcl::RangeViewProjection::Sample s;
  EXPECT_FALSE (projection.sample (Eigen::Vector3f (0.0f, 0.03f, 0.2f), s));
}

TEST (RangeViewProjection, BadArgumentsAreRefused)
{
  const pcl::ScanMesh mesh = tiltedPlane ();
  EXPECT_THROW (pcl::RangeViewProjection (mesh, 0.0), pcl::BadArgumentException);
  EXPECT_THROW (pcl::RangeViewProjection (mesh, 3.0, -1.0), pcl::BadArgumentException);
  pcl::ScanMesh empty;
  EXPECT_THROW (pcl::RangeViewProjection (empty, 3.0), pcl::InvalidScanException);
}

// Lines of sight around the view, clear of its surface by the margin, are seen empty; those through
// the surface, near its rim, through a hole it encloses, or outside the view's extent are not.
TEST (RangeViewProjection, EmptySpaceIsTheBackgroundAroundTheView)
{
  // Two 41 x 15 mm strips, 20 mm apart, joined at one end: a U whose inside is background. A hole in
  // the joining part is enclosed by surface.
  pcl::PointCloud<pcl::PointXYZ> cloud (41, 55);
  const float nan = std::numeric_limits<float>::quiet_NaN ();
  for (int r = 0; r < 55; ++r)
    for (int c = 0; c < 41; ++c)
    {
      const bool inside_u = r >= 15 && r < 35 && c >= 10;
      const bool hole = r >= 20 && r < 30 && c >= 2 && c < 7;
      cloud.at (c, r) = inside_u || hole ? pcl::PointXYZ (nan, nan, nan) : pcl::PointXYZ (1e-3f * c, 1e-3f * r, 0.0f);
    }
  cloud.is_dense = false;
  pcl::RangeScanTriangulation triangulation;
  triangulation.setViewpoint (pcl::ScanViewpoint::fromPositiveZ ());
  pcl::ScanMesh mesh;
  triangulation.triangulate (cloud, mesh);
  pcl::RangeViewProjection projection (mesh, 3.0, 2.0);  // 2 pixels per mm
  const Eigen::Vector3f inside (0.03f, 0.025f, 0.005f);
  EXPECT_FALSE (projection.seenEmpty (inside)) << "nothing is empty before markEmptySpace()";
  projection.markEmptySpace (4);  // 2 mm
  EXPECT_TRUE (projection.seenEmpty (inside));
  EXPECT_TRUE (projection.seenEmpty (Eigen::Vector3f (0.035f, 0.022f, -0.01f))) << "at any depth along the line of sight";
  EXPECT_FALSE (projection.seenEmpty (Eigen::Vector3f (0.03f, 0.0155f, 0.0f))) << "within the margin of the rim";
  EXPECT_FALSE (projection.seenEmpty (Eigen::Vector3f (0.03f, 0.005f, 0.0f))) << "on the surface";
  EXPECT_FALSE (projection.seenEmpty (Eigen::Vector3f (0.0045f, 0.025f, 0.0f))) << "in a hole the surface encloses";
  EXPECT_FALSE (projection.seenEmpty (Eigen::Vector3f (0.06f, 0.025f, 0.0f))) << "outside the view's extent";
  EXPECT_THROW (projection.markEmptySpace (-1), pcl::BadArgumentException);
}
