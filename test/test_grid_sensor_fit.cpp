/*
 * pcl_tensor: tests of fitting a pushbroom sensor to an organized scan's grid, with exact answers.
 */
#include "test_utils.h"

#include <pcl/common/grid_sensor_fit.h>
#include <pcl/io/range_scan_io.h>

namespace
{
  /** A pushbroom's scan of a wavy surface: column c is the sweep position x = 0.5 mm c (odd rows shifted
    * by half a step, as the Cyberware rows are), row r the fan angle 0.06 deg r about the axis. Every
    * 13th cell is empty. \a transposed swaps the grid's rows and columns. */
  pcl::PointCloud<pcl::PointXYZ>
  pushbroomScan (const pcl::ScanViewpoint& sensor, bool transposed)
  {
    const int sweeps = 120, fan = 90;
    pcl::PointCloud<pcl::PointXYZ> cloud (transposed ? fan : sweeps, transposed ? sweeps : fan);
    for (int r = 0; r < fan; ++r)
      for (int c = 0; c < sweeps; ++c)
      {
        const double x = 5e-4 * (c - sweeps / 2 + 0.5 * (r % 2)), angle = 1e-3 * (r - fan / 2);
        const double range = 1.3 + 0.02 * std::sin (40.0 * x) * std::cos (30.0 * angle);
        const Eigen::Vector3d s (x, range * std::sin (angle), range * std::cos (angle));
        pcl::PointXYZ p;
        p.getVector3fMap () = (sensor.sensor_pose * s).cast<float> ();
        if ((r * sweeps + c) % 13 == 0)
          p.x = p.y = p.z = std::numeric_limits<float>::quiet_NaN ();
        (transposed ? cloud.at (r, c) : cloud.at (c, r)) = p;
      }
    cloud.is_dense = false;
    return cloud;
  }

  /** Distance from \a p to the fitted sensor's axis (its x axis through its origin). */
  double
  distanceToAxis (const pcl::ScanViewpoint& v, const Eigen::Vector3d& p)
  {
    const Eigen::Vector3d d = p - v.sensor_pose.translation (), x = v.sensor_pose.linear ().col (0);
    return (d - d.dot (x) * x).norm ();
  }
}

TEST (ScanViewpoint, PushbroomLinesOfSightStayInTheirSweepPlane)
{
  const pcl::ScanViewpoint v = pcl::ScanViewpoint::pushbroom (Eigen::Vector3d (0.0, 0.2, 1.3), Eigen::Vector3d::UnitX (),
                                                              Eigen::Vector3d::Zero ());
  // Seen from the axis y = 0.2, z = 1.3, the point (0.07, 0.05, 0.1) lies along (0, -0.15, -1.2).
  const Eigen::Vector3d p (0.07, 0.05, 0.1);
  EXPECT_TRUE (v.towardSensor (p).isApprox (Eigen::Vector3d (0.0, 0.15, 1.2).normalized (), 1e-12));
  // Retinal coordinates: the sweep position and the tangent of the fan angle from the sensor's +z.
  const Eigen::Vector2d uv = v.project (p);
  EXPECT_NEAR (std::abs (uv.x ()), 0.07, 1e-12);
  const double toward_origin = std::atan2 (0.2, 1.3), toward_p = std::atan2 (0.15, 1.2);
  EXPECT_NEAR (std::abs (uv.y ()), std::tan (toward_origin - toward_p), 1e-12);
}

TEST (GridSensorFit, RecoversTheAxisOfAPushbroomGridEitherWayRound)
{
  const Eigen::Vector3d axis_point (0.01, 0.18, 1.35), axis = Eigen::Vector3d (1.0, 0.02, -0.01).normalized ();
  const pcl::ScanViewpoint truth = pcl::ScanViewpoint::pushbroom (axis_point, axis, Eigen::Vector3d (0.0, 0.0, 0.05));
  for (const bool transposed : {false, true})
  {
    const pcl::GridSensorFit fit = pcl::fitPushbroomSensor (pushbroomScan (truth, transposed));
    ASSERT_TRUE (fit.found) << "transposed " << transposed;
    EXPECT_LT (fit.fan_rms, 0.01);  // float rounding of the points only
    EXPECT_LT (fit.sweep_rms, 0.01);  // the stagger is modelled
    EXPECT_EQ (fit.viewpoint.model, pcl::ScanViewpoint::Model::pushbroom);
    EXPECT_GT (std::abs (fit.viewpoint.sensor_pose.linear ().col (0).dot (axis)), 1.0 - 1e-9);
    EXPECT_LT (distanceToAxis (fit.viewpoint, axis_point), 1e-5);
    // It looks toward the scan.
    EXPECT_GT (fit.viewpoint.towardSensor (Eigen::Vector3d (0.0, 0.0, 0.05)).dot (truth.towardSensor (Eigen::Vector3d (0.0, 0.0, 0.05))), 1.0 - 1e-6);
  }
}

TEST (GridSensorFit, RefusesGridsNoPushbroomExplains)
{
  // A perspective sensor's columns fan out in x as well: no sweep keeps them in place.
  const pcl::ScanViewpoint camera = pcl::ScanViewpoint::lookingAt (Eigen::Vector3d (0.0, 0.0, 1.0), Eigen::Vector3d::Zero ());
  pcl::PointCloud<pcl::PointXYZ> perspective (100, 80);
  for (int r = 0; r < 80; ++r)
    for (int c = 0; c < 100; ++c)
    {
      const Eigen::Vector3d ray ((c - 50) * 0.007, (r - 40) * 0.007, 1.0);
      const double depth = 1.0 + 0.1 * std::sin (9.0 * ray.x ()) + 0.05 * ray.y ();
      perspective.at (c, r).getVector3fMap () = (camera.sensor_pose * (depth * ray)).cast<float> ();
    }
  EXPECT_FALSE (pcl::fitPushbroomSensor (perspective).found);

  // An unorganized cloud has no grid to fit.
  pcl::PointCloud<pcl::PointXYZ> unorganized;
  for (const auto& p : perspective)
    unorganized.push_back (p);
  EXPECT_FALSE (pcl::fitPushbroomSensor (unorganized).found);
}

TEST (GridSensorFit, StanfordBunnyScansArePushbroomScans)
{
  PCL_TENSOR_REQUIRE_SHARED_DATA (path, "stanford/bunny/bun000.ply");
  const pcl::io::RangeScan scan = pcl::io::loadRangeScan (path);
  const pcl::GridSensorFit fit = pcl::fitPushbroomSensor (*scan.cloud);
  ASSERT_TRUE (fit.found);
  // The sweep runs along x, from the line at y = 0.18 m, z = 1.35 m (measured: see grid_sensor_fit.h).
  EXPECT_GT (std::abs (fit.viewpoint.sensor_pose.linear ().col (0).x ()), 1.0 - 1e-6);
  EXPECT_LT (distanceToAxis (fit.viewpoint, Eigen::Vector3d (0.0, 0.181, 1.351)), 2e-3);
  EXPECT_EQ (scan.viewpoint.model, pcl::ScanViewpoint::Model::pushbroom) << "loadRangeScan uses the fit";
}

TEST (GridSensorFit, DegenerateGridsAreNotFitted)
{
  // All points equal, a flat sheet seen edge-on, and coordinates that overflow the scatter's squares.
  pcl::PointCloud<pcl::PointXYZ> same (40, 30), line (40, 30), huge (40, 30);
  for (int r = 0; r < 30; ++r)
    for (int c = 0; c < 40; ++c)
    {
      same.at (c, r) = pcl::PointXYZ (1.0f, 2.0f, 3.0f);
      line.at (c, r) = pcl::PointXYZ (0.001f * c, 0.0f, 1.0f);
      huge.at (c, r) = pcl::PointXYZ (1e30f * c, 1e30f * r, 1e30f * (c + r));
    }
  for (const auto* cloud : {&same, &line, &huge})
    EXPECT_FALSE (pcl::fitPushbroomSensor (*cloud).found);
  // Too few lines to tell a fan from a sweep.
  pcl::PointCloud<pcl::PointXYZ> narrow (40, 2);
  for (auto& p : narrow)
    p = pcl::PointXYZ (0.1f, 0.2f, 1.0f);
  EXPECT_FALSE (pcl::fitPushbroomSensor (narrow).found);
}
