#include "test_utils.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/io/range_scan_io.h>
#include <pcl/surface/scan_preparation.h>
#include <pcl/surface/range_scan_triangulation.h>

namespace
{
  using Method = pcl::ScanMeshNormalEstimation::Method;

  /** A tilted plane z = 0.3 x + 0.2 y sampled on a grid: every normal is known exactly. */
  pcl::PointCloud<pcl::PointXYZ>
  tiltedPlane ()
  {
    pcl::PointCloud<pcl::PointXYZ> cloud (30, 20);
    for (int r = 0; r < 20; ++r)
      for (int c = 0; c < 30; ++c)
        cloud.at (c, r) = pcl::PointXYZ (0.01f * c, 0.01f * r, 0.003f * c + 0.002f * r);
    return cloud;
  }
}

TEST (ScanMeshNormals, BothMethodsRecoverAPlaneNormalTowardTheSensor)
{
  const Eigen::Vector3f expected = Eigen::Vector3f (-0.3f, -0.2f, 1.0f).normalized ();
  for (const Method method : {Method::FACE_AVERAGE, Method::FINE_NEIGHBOURHOOD})
  {
    pcl::ScanPreparationParams params;
    params.normal_method = method;
    params.target_faces = 100;
    const pcl::PreparedScan scan = pcl::prepareScan (tiltedPlane (), pcl::ScanViewpoint::fromPositiveZ (), params);
    for (const auto& p : *scan.reduced.cloud)
      EXPECT_GT (p.getNormalVector3fMap ().dot (expected), 1.0f - 1e-5f);
  }
}

TEST (ScanPreparation, ReductionFromEverySecondRowAndColumnStaysOnTheSurface)
{
  // A dome z = 0.2 - (x^2 + y^2) on a 200 x 200 grid: reduced from the 100 x 100 subgrid, M'_i still
  // has the target's faces, every vertex on the surface, and its normals from the full grid.
  pcl::PointCloud<pcl::PointXYZ> dome (200, 200);
  for (int r = 0; r < 200; ++r)
    for (int c = 0; c < 200; ++c)
    {
      const float x = 0.002f * (c - 100), y = 0.002f * (r - 100);
      dome.at (c, r) = pcl::PointXYZ (x, y, 0.2f - (x * x + y * y));
    }
  for (const int step : {1, 2})
  {
    pcl::ScanPreparationParams params;
    params.target_faces = 400;
    params.reduction_grid_step = step;
    const pcl::PreparedScan scan = pcl::prepareScan (dome, pcl::ScanViewpoint::fromPositiveZ (), params);
    EXPECT_NEAR (static_cast<double> (scan.reduced.polygons.size ()), 400.0, 40.0) << "step " << step;
    EXPECT_NEAR (scan.resolution, 0.002, 0.0005);  // d_res is the full grid's
    for (const auto& p : *scan.reduced.cloud)
    {
      EXPECT_NEAR (p.z, 0.2f - (p.x * p.x + p.y * p.y), 1e-6f);
      const Eigen::Vector3f expected = Eigen::Vector3f (2.0f * p.x, 2.0f * p.y, 1.0f).normalized ();
      EXPECT_GT (p.getNormalVector3fMap ().dot (expected), 0.999f);
    }
  }
  // Too few points for the target on the subgrid: M_i itself is reduced, to the same mesh as step 1.
  pcl::ScanPreparationParams coarse, fine;
  coarse.target_faces = fine.target_faces = 4000;
  coarse.reduction_grid_step = 2;
  EXPECT_EQ (pcl::prepareScan (dome, pcl::ScanViewpoint::fromPositiveZ (), coarse).reduced.polygons.size (),
             pcl::prepareScan (dome, pcl::ScanViewpoint::fromPositiveZ (), fine).reduced.polygons.size ());
}

TEST (ScanMeshNormals, BunnyNormalsAreUnitAndFaceTheSensor)
{
  for (const auto& name : pcl_tensor_test::bunnyScanNames ())
  {
    PCL_TENSOR_REQUIRE_SHARED_DATA (path, name);
    const pcl::io::RangeScan scan = pcl::io::loadRangeScan (path);
    for (const Method method : {Method::FACE_AVERAGE, Method::FINE_NEIGHBOURHOOD})
    {
      pcl::ScanPreparationParams params;
      params.normal_method = method;
      const pcl::PreparedScan prepared = pcl::prepareScan (*scan.cloud, scan.viewpoint, params);
      std::size_t facing = 0;
      for (const auto& p : *prepared.reduced.cloud)
      {
        EXPECT_NEAR (p.getNormalVector3fMap ().norm (), 1.0f, 1e-5f);
        // Facing: the normal points to the sensor's side of the surface (Section 2).
        const Eigen::Vector3d toward = prepared.reduced.viewpoint.towardSensor (p.getVector3fMap ().cast<double> ());
        facing += p.getNormalVector3fMap ().cast<double> ().dot (toward) > 0.0;
      }
      EXPECT_GE (static_cast<double> (facing), 0.99 * static_cast<double> (prepared.reduced.cloud->size ())) << name;
    }
  }
}

TEST (ScanMeshNormals, FineMeshGetsNormalsWithEitherMethod)
{
  // Verification's point-to-plane ICP reads M_i's normals, whichever approach M'_i uses.
  const Eigen::Vector3f expected = Eigen::Vector3f (-0.3f, -0.2f, 1.0f).normalized ();
  for (const Method method : {Method::FACE_AVERAGE, Method::FINE_NEIGHBOURHOOD})
  {
    pcl::ScanPreparationParams params;
    params.normal_method = method;
    params.target_faces = 100;
    const pcl::PreparedScan scan = pcl::prepareScan (tiltedPlane (), pcl::ScanViewpoint::fromPositiveZ (), params);
    for (const auto& p : *scan.fine.cloud)
      EXPECT_GT (p.getNormalVector3fMap ().dot (expected), 1.0f - 1e-5f);
  }
}

TEST (ScanMeshNormals, MeshesWithoutFacesAndBadRadiusThrow)
{
  pcl::ScanMeshNormalEstimation estimation;
  pcl::ScanMesh empty, other;
  EXPECT_THROW (estimation.compute (empty, other), pcl::InvalidScanException);
  EXPECT_THROW (estimation.computeFaceAverage (empty), pcl::InvalidScanException);
  EXPECT_THROW (estimation.setRadiusResolutions (0.0), pcl::BadArgumentException);
}
