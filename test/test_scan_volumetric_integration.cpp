/*
 * pcl_tensor: tests of the volumetric integration (Curless & Levoy 1996) of registered range views.
 */
#include "test_utils.h"

#include <pcl/common/point_mesh_distance.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/simulation/example_object.h>
#include <pcl/simulation/synthetic_views.h>
#include <pcl/surface/range_scan_triangulation.h>
#include <pcl/surface/scan_volumetric_integration.h>

#include <algorithm>
#include <map>

namespace
{
  /** An analytic sphere seen by the synthetic camera: each pixel's ray meets the sphere exactly. */
  struct Sphere
  {
    Eigen::Vector3d centre;
    double radius;
  };

  /** The view of \a sphere from \a sensor_pose (sensor -> world) as a registered fine mesh M_i. */
  pcl::IntegrationView
  sphereView (const Sphere& sphere, const Eigen::Affine3d& sensor_pose, const pcl::RangeCameraParams& camera)
  {
    pcl::ZBufferRangeRenderer renderer;
    renderer.setCameraParams (camera);
    pcl::PointCloud<pcl::PointXYZ> cloud (camera.width, camera.height);
    const Eigen::Vector3d c = sensor_pose.inverse () * sphere.centre;
    for (int r = 0; r < camera.height; ++r)
      for (int col = 0; col < camera.width; ++col)
      {
        const pcl::PixelRay ray = renderer.pixelRay (col, r);
        // |o + t d - c|^2 = R^2, nearest root.
        const Eigen::Vector3d oc = ray.origin - c;
        const double a = ray.direction.squaredNorm (), b = oc.dot (ray.direction);
        const double disc = b * b - a * (oc.squaredNorm () - sphere.radius * sphere.radius);
        pcl::PointXYZ& p = cloud.at (col, r);
        if (disc < 0.0)
          p.x = p.y = p.z = std::numeric_limits<float>::quiet_NaN ();
        else
          p.getVector3fMap () = (ray.origin + (-b - std::sqrt (disc)) / a * ray.direction).cast<float> ();
      }
    cloud.is_dense = false;
    // The renderer's convention: the camera looks down its -z axis (RenderedView::viewpoint).
    pcl::ScanViewpoint viewpoint;
    viewpoint.sensor_pose = Eigen::AngleAxisd (M_PI, Eigen::Vector3d::UnitX ());
    viewpoint.model = camera.orthographic ? pcl::ScanViewpoint::Model::orthographic : pcl::ScanViewpoint::Model::perspective;
    pcl::RangeScanTriangulation triangulation;
    triangulation.setViewpoint (viewpoint);
    auto mesh = std::make_shared<pcl::ScanMesh> ();
    triangulation.triangulate (cloud, *mesh);
    return {mesh, sensor_pose};
  }

  std::vector<pcl::IntegrationView>
  sphereViews (const Sphere& sphere, const pcl::ViewDirections& directions, const pcl::RangeCameraParams& camera)
  {
    const pcl::ViewTarget target{sphere.centre, sphere.radius};
    const double distance = pcl::fittingDistance (target, camera);
    std::vector<pcl::IntegrationView> views;
    for (const auto& pose : pcl::lookAtPoses (directions, target, distance))
      views.push_back (sphereView (sphere, pose, camera));
    return views;
  }

  /** Each undirected edge with the number of triangles using it. */
  std::map<std::pair<int, int>, int>
  edgeUses (const pcl::ScanMesh& mesh)
  {
    std::map<std::pair<int, int>, int> uses;
    for (const auto& poly : mesh.polygons)
      for (int k = 0; k < 3; ++k)
      {
        const int a = poly.vertices[k], b = poly.vertices[(k + 1) % 3];
        ++uses[{std::min (a, b), std::max (a, b)}];
      }
    return uses;
  }

  const Sphere kSphere{Eigen::Vector3d (0.01, 0.02, -0.03), 0.05};

  pcl::RangeCameraParams
  smallCamera ()
  {
    pcl::RangeCameraParams camera;
    camera.width = camera.height = 160;
    return camera;
  }
}

// 26 exact views of a sphere integrate to a closed surface within a small fraction of a voxel of it,
// with outward normals.
TEST (ScanVolumetricIntegration, SphereIsRecoveredWithinAFractionOfAVoxel)
{
  pcl::ScanVolumetricIntegration integration;
  integration.setInputViews (sphereViews (kSphere, pcl::makeDefaultViewDirections (), smallCamera ()));
  pcl::ScanMesh model;
  integration.reconstruct (model);
  const auto& report = integration.getReport ();
  ASSERT_GT (model.polygons.size (), 1000u);
  EXPECT_EQ (report.components, 1u);
  EXPECT_NEAR (report.voxel_size, report.resolution, 1e-12);

  std::vector<double> errors;
  for (const auto& p : *model.cloud)
  {
    const Eigen::Vector3d x = p.getVector3fMap ().cast<double> () - kSphere.centre;
    errors.push_back (std::abs (x.norm () - kSphere.radius) / report.voxel_size);
    EXPECT_GT (p.getNormalVector3fMap ().cast<double> ().dot (x.normalized ()), 0.9);
  }
  EXPECT_LT (pcl_tensor_test::median (errors), 0.05);
  EXPECT_LT (*std::max_element (errors.begin (), errors.end ()), 0.25);
  // Welded and closed: every edge is shared by exactly two triangles.
  for (const auto& e : edgeUses (model))
    ASSERT_EQ (e.second, 2) << "edge " << e.first.first << "-" << e.first.second;
}

// Threads share a view's voxel blocks, and views are added in order: the model is the same, bit for
// bit, on 1, 2 and 4 threads.
TEST (ScanVolumetricIntegration, ModelIsTheSameOnAnyNumberOfThreads)
{
  const auto views = sphereViews (kSphere, pcl::makeDefaultViewDirections (), smallCamera ());
  std::vector<pcl::ScanMesh> models (3);
  const unsigned threads[] = {1, 2, 4};
  for (std::size_t k = 0; k < models.size (); ++k)
  {
    pcl::ScanVolumetricIntegration integration;
    integration.setNumberOfThreads (threads[k]);
    integration.setInputViews (views);
    integration.reconstruct (models[k]);
  }
  ASSERT_GT (models[0].polygons.size (), 1000u);
  for (std::size_t k = 1; k < models.size (); ++k)
  {
    ASSERT_EQ (models[k].cloud->size (), models[0].cloud->size ()) << threads[k] << " threads";
    ASSERT_EQ (models[k].polygons.size (), models[0].polygons.size ()) << threads[k] << " threads";
    for (std::size_t i = 0; i < models[0].cloud->size (); ++i)
      ASSERT_EQ ((*models[k].cloud)[i].getVector3fMap (), (*models[0].cloud)[i].getVector3fMap ()) << threads[k] << " threads, vertex " << i;
    for (std::size_t t = 0; t < models[0].polygons.size (); ++t)
      ASSERT_EQ (models[k].polygons[t].vertices, models[0].polygons[t].vertices) << threads[k] << " threads, triangle " << t;
  }
}

// An orthographic sensor's parallel lines of sight give the same surface.
TEST (ScanVolumetricIntegration, OrthographicViewsRecoverTheSphere)
{
  pcl::RangeCameraParams camera = smallCamera ();
  camera.orthographic = true;
  camera.ortho_extent = 2.2 * kSphere.radius;
  pcl::ScanVolumetricIntegration integration;
  integration.setInputViews (sphereViews (kSphere, pcl::makeDefaultViewDirections (), camera));
  pcl::ScanMesh model;
  integration.reconstruct (model);
  ASSERT_GT (model.polygons.size (), 1000u);
  std::vector<double> errors;
  for (const auto& p : *model.cloud)
    errors.push_back (std::abs ((p.getVector3fMap ().cast<double> () - kSphere.centre).norm () - kSphere.radius)
                      / integration.getReport ().voxel_size);
  EXPECT_LT (pcl_tensor_test::median (errors), 0.05);
  EXPECT_LT (*std::max_element (errors.begin (), errors.end ()), 0.25);
}

// One view sees a cap of the sphere: the model is that cap only. Nothing closes it behind, and
// no surface appears between the seen band and unseen space.
TEST (ScanVolumetricIntegration, UnseenSpaceMakesNoSurface)
{
  const pcl::ViewDirections one{Eigen::Vector3d::UnitZ ()};
  pcl::ScanVolumetricIntegration integration;
  integration.setInputViews (sphereViews (kSphere, one, smallCamera ()));
  pcl::ScanMesh model;
  integration.reconstruct (model);
  ASSERT_GT (model.polygons.size (), 100u);
  const double voxel = integration.getReport ().voxel_size;
  for (const auto& p : *model.cloud)
  {
    const Eigen::Vector3d x = p.getVector3fMap ().cast<double> () - kSphere.centre;
    ASSERT_LT (std::abs (x.norm () - kSphere.radius), 0.25 * voxel);
    ASSERT_GT (x.z (), 0.0) << "a vertex on the unseen side of the sphere";
  }
  // The cap is open: its rim has edges of one triangle.
  std::size_t border = 0;
  for (const auto& e : edgeUses (model))
    border += e.second == 1 ? 1 : 0;
  EXPECT_GT (border, 0u);
}

// A voxel grid too fine for the memory limit is refused before it is allocated.
TEST (ScanVolumetricIntegration, MemoryLimitIsRefused)
{
  pcl::ScanVolumetricIntegration integration;
  integration.setInputViews (sphereViews (kSphere, pcl::makeRingViewDirections (2, 180.0), smallCamera ()));
  integration.setMaxMemoryBytes (std::size_t (16) << 20);
  integration.setVoxelSize (kSphere.radius / 2000.0);
  pcl::ScanMesh model;
  EXPECT_THROW (integration.reconstruct (model), pcl::MemoryLimitException);
  // The same views at their own resolution fit.
  integration.setVoxelSize (0.0);
  EXPECT_NO_THROW (integration.reconstruct (model));
  EXPECT_LE (integration.getReport ().volume_bytes, std::size_t (16) << 20);
}

// A view placed beyond the volume's block coordinates is refused, found on whichever thread looks
// at it, before anything is allocated.
TEST (ScanVolumetricIntegration, ViewsBeyondTheBlockRangeAreRefused)
{
  auto views = sphereViews (kSphere, pcl::makeRingViewDirections (2, 180.0), smallCamera ());
  views[1].pose = Eigen::Translation3d (1.0e6, 0.0, 0.0) * views[1].pose;
  pcl::ScanVolumetricIntegration integration;
  integration.setNumberOfThreads (2);
  integration.setInputViews (views);
  pcl::ScanMesh model;
  EXPECT_THROW (integration.reconstruct (model), pcl::MemoryLimitException);
}

TEST (ScanVolumetricIntegration, BadInputIsRefused)
{
  pcl::ScanVolumetricIntegration integration;
  pcl::ScanMesh model;
  EXPECT_THROW (integration.reconstruct (model), pcl::InvalidScanException);
  integration.setInputViews ({pcl::IntegrationView ()});
  EXPECT_THROW (integration.reconstruct (model), pcl::InvalidScanException);
  EXPECT_THROW (integration.setVoxelSize (-1.0), pcl::BadArgumentException);
  pcl::VolumetricIntegrationParams params;
  params.truncation_voxels = 0.0;
  EXPECT_THROW (integration.setParams (params), pcl::BadArgumentException);
}

// Issue 6 / the paper's Fig. 12: the model rebuilt from the 26 synthetic views of the built-in object,
// at their exact poses, lies within a median distance of 0.5 d_res of the original.
TEST (ScanVolumetricIntegration, ExampleObjectFromItsSyntheticViews)
{
  const pcl::ScanMesh object = pcl::makeExampleObject ();
  const auto rendered = pcl::renderSyntheticViews (object, pcl::makeDefaultViewDirections (), pcl::SyntheticViewParams ());
  std::vector<pcl::IntegrationView> views;
  for (const auto& v : rendered)
  {
    pcl::RangeScanTriangulation triangulation;
    triangulation.setViewpoint (v.view.viewpoint);
    auto mesh = std::make_shared<pcl::ScanMesh> ();
    triangulation.triangulate (*v.view.cloud, *mesh);
    views.push_back ({mesh, v.view.pose});
  }
  pcl::ScanVolumetricIntegration integration;
  integration.setInputViews (views);
  pcl::ScanMesh model;
  integration.reconstruct (model);
  const double resolution = integration.getReport ().resolution;
  ASSERT_GT (model.polygons.size (), 1000u);
  EXPECT_EQ (integration.getReport ().components, 1u);

  pcl::PointMeshDistance to_object, to_model;
  to_object.setMesh (object);
  to_model.setMesh (model);
  std::vector<double> model_error, coverage_error;
  for (const auto& p : *model.cloud)
    model_error.push_back (to_object.distance (p.getVector3fMap ().cast<double> ()) / resolution);
  for (const auto& p : *object.cloud)
    coverage_error.push_back (to_model.distance (p.getVector3fMap ().cast<double> ()) / resolution);
  EXPECT_LT (pcl_tensor_test::median (model_error), 0.5);
  // ... and covers the whole object: no part of it is missing from the model.
  EXPECT_LT (*std::max_element (coverage_error.begin (), coverage_error.end ()), 2.0);
}

// Views added to a kept volume give the voxels, and so the surface, of integrating every view at once
// at the same voxel size: a view's distances reach only blocks near its own surface.
TEST (ScanVolumetricIntegration, ViewsAddedToAKeptVolumeGiveTheSameSurface)
{
  const auto views = sphereViews (kSphere, pcl::makeDefaultViewDirections (), smallCamera ());
  const std::size_t first = views.size () / 2;
  pcl::ScanVolumetricIntegration all;
  all.setInputViews (views);
  pcl::ScanMesh at_once;
  all.reconstruct (at_once);
  EXPECT_FALSE (all.getVolume ()) << "the voxels are kept only when asked";

  pcl::ScanVolumetricIntegration before;
  before.setVoxelSize (all.getReport ().voxel_size);
  before.setKeepVolume (true);
  before.setInputViews (std::vector<pcl::IntegrationView> (views.begin (), views.begin () + first));
  pcl::ScanMesh part;
  before.reconstruct (part);
  const pcl::IntegrationVolume::ConstPtr kept = before.getVolume ();
  ASSERT_TRUE (kept && kept->isConsistent ());
  EXPECT_EQ (kept->views, first);

  pcl::ScanVolumetricIntegration after;
  after.setInitialVolume (kept);
  after.setInputViews (std::vector<pcl::IntegrationView> (views.begin () + first, views.end ()));
  pcl::ScanMesh extended;
  after.reconstruct (extended);
  EXPECT_EQ (after.getReport ().views, views.size ());
  EXPECT_EQ (after.getReport ().initial_views, first);
  EXPECT_DOUBLE_EQ (after.getReport ().voxel_size, all.getReport ().voxel_size);
  EXPECT_EQ (after.getReport ().blocks, all.getReport ().blocks);
  EXPECT_EQ (after.getReport ().observed_voxels, all.getReport ().observed_voxels);
  // The same surface: the vertices in another order (blocks are listed in another order), each within
  // float rounding of one of the other mesh's.
  ASSERT_EQ (extended.cloud->size (), at_once.cloud->size ());
  ASSERT_EQ (extended.polygons.size (), at_once.polygons.size ());
  pcl::PointMeshDistance distance;
  distance.setMesh (at_once);
  double worst = 0.0;
  for (const auto& p : *extended.cloud)
    worst = std::max (worst, distance.distance (p.getVector3fMap ().cast<double> ()));
  EXPECT_LT (worst, 1e-4 * all.getReport ().voxel_size);
}

TEST (ScanVolumetricIntegration, InconsistentInitialVolumeIsRefused)
{
  auto volume = std::make_shared<pcl::IntegrationVolume> ();
  volume->voxel_size = 0.001;
  volume->blocks.emplace_back (0, 0, 0);
  volume->distance.resize (10);
  pcl::ScanVolumetricIntegration integration;
  integration.setInitialVolume (volume);
  pcl::ScanMesh model;
  EXPECT_THROW (integration.reconstruct (model), pcl::InvalidScanException);
}
