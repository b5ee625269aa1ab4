/*
 * pcl_tensor: tests of pcl::ZBufferRangeRenderer (exact ray casting, occlusion, ground-truth poses).
 */
#include "test_utils.h"

#include <pcl/common/point_mesh_distance.h>
#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/io/scan_mesh_io.h>
#include <pcl/simulation/example_object.h>
#include <pcl/simulation/view_set.h>
#include <pcl/simulation/zbuffer_range_renderer.h>

#include <iostream>
#include <limits>
#include <map>

namespace
{
  /** A sphere of radius \a r at \a centre: an icosahedron subdivided \a levels times, with every
    * vertex on the true sphere, so each triangle lies inside the sphere by at most its chord sag. */
  pcl::ScanMesh
  icosphere (int levels, double r, const Eigen::Vector3d& centre)
  {
    const double t = (1.0 + std::sqrt (5.0)) / 2.0;
    std::vector<Eigen::Vector3d> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                      {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (auto& p : v)
      p.normalize ();
    std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9},
                                         {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2},
                                         {3, 2, 6}, {3, 6, 8}, {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10},
                                         {8, 6, 7}, {9, 8, 1}};
    for (int l = 0; l < levels; ++l)
    {
      std::map<std::pair<int, int>, int> mid;
      auto m = [&] (int a, int b) {
        const auto key = std::minmax (a, b);
        auto it = mid.find (key);
        if (it != mid.end ())
          return it->second;
        v.push_back ((v[a] + v[b]).normalized ());
        return mid[key] = static_cast<int> (v.size ()) - 1;
      };
      std::vector<std::array<int, 3>> g;
      for (const auto& x : f)
      {
        const int ab = m (x[0], x[1]), bc = m (x[1], x[2]), ca = m (x[2], x[0]);
        g.push_back ({x[0], ab, ca});
        g.push_back ({x[1], bc, ab});
        g.push_back ({x[2], ca, bc});
        g.push_back ({ab, bc, ca});
      }
      f.swap (g);
    }
    pcl::ScanMesh mesh;
    for (const auto& p : v)
    {
      pcl::PointNormal q;
      q.getVector3fMap () = (centre + r * p).cast<float> ();
      mesh.cloud->push_back (q);
    }
    for (const auto& x : f)
    {
      pcl::Vertices tri;
      tri.vertices = {x[0], x[1], x[2]};
      mesh.polygons.push_back (tri);
    }
    return mesh;
  }

  /** Largest radial gap between the tessellation and the sphere: R - sqrt(R^2 - rho^2) over the
    * triangles' circumradii rho (the vertices are on the sphere; the centre is the mesh centroid). */
  double
  maxChordSag (const pcl::ScanMesh& mesh, double r)
  {
    double sag = 0.0;
    for (const auto& tri : mesh.polygons)
    {
      const Eigen::Vector3d a = (*mesh.cloud)[tri.vertices[0]].getVector3fMap ().cast<double> ();
      const Eigen::Vector3d b = (*mesh.cloud)[tri.vertices[1]].getVector3fMap ().cast<double> ();
      const Eigen::Vector3d c = (*mesh.cloud)[tri.vertices[2]].getVector3fMap ().cast<double> ();
      const double la = (b - c).norm (), lb = (c - a).norm (), lc = (a - b).norm ();
      const double rho = la * lb * lc / (2.0 * (b - a).cross (c - a).norm ());
      sag = std::max (sag, r - std::sqrt (std::max (0.0, r * r - rho * rho)));
    }
    return sag;
  }

  /** An axis-aligned square of half-size \a h at height \a z (normal along z). */
  void
  addSquare (pcl::ScanMesh& mesh, double h, double z)
  {
    const int base = static_cast<int> (mesh.cloud->size ());
    for (const auto& xy : {Eigen::Vector2d (-h, -h), Eigen::Vector2d (h, -h), Eigen::Vector2d (h, h), Eigen::Vector2d (-h, h)})
    {
      pcl::PointNormal p;
      p.x = static_cast<float> (xy.x ());
      p.y = static_cast<float> (xy.y ());
      p.z = static_cast<float> (z);
      mesh.cloud->push_back (p);
    }
    pcl::Vertices t1, t2;
    t1.vertices = {base, base + 1, base + 2};
    t2.vertices = {base, base + 2, base + 3};
    mesh.polygons.push_back (t1);
    mesh.polygons.push_back (t2);
  }

  /** Largest distance from a view's points, mapped by its ground truth, to the mesh. */
  double
  maxDistanceToMesh (const pcl::RenderedView& view, const pcl::PointMeshDistance& distance, std::size_t& finite)
  {
    double worst = 0.0;
    finite = 0;
    for (const auto& p : *view.cloud)
      if (pcl::isXYZFinite (p))
      {
        ++finite;
        worst = std::max (worst, distance.distance (view.pose * p.getVector3fMap ().cast<double> ()));
      }
    return worst;
  }

  /** Every view of \a mesh lies on \a mesh to within 1e-6 of the object's size. */
  void
  expectViewsOnMesh (const pcl::ScanMesh& mesh, const pcl::ViewDirections& directions, int size)
  {
    pcl::RangeCameraParams camera;
    camera.width = camera.height = size;
    pcl::ZBufferRangeRenderer renderer;
    renderer.setMesh (mesh);
    renderer.setCameraParams (camera);
    const auto target = pcl::boundingTarget (mesh);
    const auto poses = pcl::lookAtPoses (directions, target, pcl::fittingDistance (target, camera));
    pcl::PointMeshDistance distance;
    distance.setMesh (mesh);
    const double object_size = 2.0 * target.radius;
    double overall = 0.0;
    std::size_t total = 0;
    for (std::size_t i = 0; i < poses.size (); ++i)
    {
      const auto view = renderer.render (poses[i]);
      std::size_t finite = 0;
      const double worst = maxDistanceToMesh (view, distance, finite);
      EXPECT_GT (finite, static_cast<std::size_t> (size * size / 20)) << "view " << i;
      EXPECT_LE (worst, 1e-6 * object_size) << "view " << i << ": " << finite << " points";
      overall = std::max (overall, worst);
      total += finite;
    }
    std::cout << "[   INFO   ] " << poses.size () << " views, " << total << " points: max distance to the mesh "
              << overall << " m = " << overall / object_size << " of the object size" << std::endl;
  }
}

// Known answer: the renderer against the analytic sphere. The mesh is a tessellated sphere, whose
// triangles sit inside the true sphere by at most the chord sag s (computed from the mesh). A ray
// meeting the sphere at incidence angle i then travels at most about s / cos(i) further, so away from
// the silhouette (cos i >= 0.6) the rendered range must match the analytic one within 1e-5 R.
TEST (ZBufferRangeRenderer, SphereMatchesAnalyticRange)
{
  const double r = 0.1;
  const Eigen::Vector3d centre (0.01, -0.02, -0.5);
  const auto mesh = icosphere (8, r, centre);
  const double sag = maxChordSag (mesh, r);
  ASSERT_LT (sag / 0.6, 1e-5 * r) << "tessellation too coarse for the bound";

  pcl::ZBufferRangeRenderer renderer;
  renderer.setMesh (mesh);
  pcl::RangeCameraParams camera;
  camera.width = 160;
  camera.height = 120;
  camera.fov_deg = 30.0;
  renderer.setCameraParams (camera);
  const auto view = renderer.render (Eigen::Affine3d::Identity ());
  ASSERT_EQ (view.cloud->width, 160u);
  ASSERT_EQ (view.cloud->height, 120u);

  int checked = 0, missed = 0, phantom = 0;
  double worst = 0.0;
  for (int row = 0; row < camera.height; ++row)
    for (int col = 0; col < camera.width; ++col)
    {
      const auto ray = renderer.pixelRay (col, row);
      const Eigen::Vector3d d = ray.direction.normalized ();
      // |o + s d - c|^2 = r^2 with unit d: s = b - sqrt(b^2 - |o - c|^2 + r^2), b = d.(c - o).
      const double b = d.dot (centre - ray.origin);
      const double disc = b * b - (centre - ray.origin).squaredNorm () + r * r;
      const auto& p = view.cloud->at (col, row);
      const bool hit = pcl::isXYZFinite (p);
      if (disc < 0.0)
      {
        phantom += hit ? 1 : 0;  // the tessellation is inside the sphere, so it cannot be hit either
        continue;
      }
      const double s = b - std::sqrt (disc);
      const Eigen::Vector3d normal = (ray.origin + s * d - centre) / r;
      if (-normal.dot (d) < 0.6)
        continue;
      if (!hit)
      {
        ++missed;
        continue;
      }
      const double range = (p.getVector3fMap ().cast<double> () - ray.origin).norm ();
      worst = std::max (worst, std::abs (range - s));
      ++checked;
    }
  EXPECT_EQ (phantom, 0);
  EXPECT_EQ (missed, 0);
  EXPECT_GT (checked, 3000);
  EXPECT_LE (worst, 1e-5 * r);
  std::cout << "[   INFO   ] " << checked << " rays: max range error " << worst / r << " R (chord sag bound "
            << sag / 0.6 / r << " R)" << std::endl;
}

// Every rendered point of the sphere, silhouette included, lies between the sphere and the chord sag.
TEST (ZBufferRangeRenderer, OrthographicSpherePointsLieInTheShell)
{
  const double r = 0.1;
  const Eigen::Vector3d centre (0.0, 0.0, -1.0);
  const auto mesh = icosphere (5, r, centre);
  const double sag = maxChordSag (mesh, r);
  pcl::ZBufferRangeRenderer renderer;
  renderer.setMesh (mesh);
  pcl::RangeCameraParams camera;
  camera.width = camera.height = 100;
  camera.orthographic = true;
  camera.ortho_extent = 0.25;
  renderer.setCameraParams (camera);
  const auto view = renderer.render (Eigen::Affine3d::Identity ());
  int finite = 0;
  for (const auto& p : *view.cloud)
    if (pcl::isXYZFinite (p))
    {
      ++finite;
      const double radial = (p.getVector3fMap ().cast<double> () - centre).norm ();
      EXPECT_LE (radial, r + 1e-7);
      EXPECT_GE (radial, r - sag - 1e-7);
      EXPECT_GE (p.z, centre.z () - 1e-6);  // only the half facing the sensor (toward z = 0) is seen
    }
  // The disc of radius r covers pi r^2 / pixel^2 pixels.
  const double pixel = camera.ortho_extent / camera.width;
  EXPECT_NEAR (finite, M_PI * r * r / (pixel * pixel), 0.02 * M_PI * r * r / (pixel * pixel));
}

// Occlusion: of two parallel planes filling the view, only the nearer one is seen, whatever the
// order of the triangles in the mesh.
TEST (ZBufferRangeRenderer, NearerOfTwoParallelPlanesOccludes)
{
  for (bool near_first : {true, false})
  {
    pcl::ScanMesh mesh;
    addSquare (mesh, near_first ? 3.0 : 6.0, near_first ? -1.0 : -2.0);
    addSquare (mesh, near_first ? 6.0 : 3.0, near_first ? -2.0 : -1.0);
    pcl::ZBufferRangeRenderer renderer;
    renderer.setMesh (mesh);
    pcl::RangeCameraParams camera;
    camera.width = 64;
    camera.height = 48;
    camera.fov_deg = 60.0;
    renderer.setCameraParams (camera);
    const auto view = renderer.render (Eigen::Affine3d::Identity ());
    for (int row = 0; row < camera.height; ++row)
      for (int col = 0; col < camera.width; ++col)
      {
        const auto& p = view.cloud->at (col, row);
        ASSERT_TRUE (pcl::isXYZFinite (p)) << col << "," << row;
        const Eigen::Vector3d expected = renderer.pixelRay (col, row).direction;  // z = -1 on the near plane
        EXPECT_NEAR ((p.getVector3fMap ().cast<double> () - expected).norm (), 0.0, 1e-6);
      }
  }
}

// The ground-truth pose maps the view back onto the mesh: move the planes' scene rigidly, render it
// from the moved sensor, and the image must not change.
TEST (ZBufferRangeRenderer, PoseIsTheSensorFrameInTheModel)
{
  pcl::ScanMesh mesh;
  addSquare (mesh, 1.0, 0.0);
  const Eigen::Affine3d sensor = Eigen::Translation3d (0.2, -0.1, 2.0) * Eigen::AngleAxisd (0.1, Eigen::Vector3d (1, 1, 0).normalized ());
  pcl::ZBufferRangeRenderer renderer;
  renderer.setMesh (mesh);
  pcl::RangeCameraParams camera;
  camera.width = camera.height = 32;
  renderer.setCameraParams (camera);
  const auto view = renderer.render (sensor);
  EXPECT_TRUE (view.pose.isApprox (sensor, 1e-15));
  int finite = 0;
  for (const auto& p : *view.cloud)
    if (pcl::isXYZFinite (p))
    {
      ++finite;
      EXPECT_LT (p.z, 0.0f);  // the sensor looks down its -z axis
      EXPECT_NEAR ((view.pose * p.getVector3fMap ().cast<double> ()).z (), 0.0, 1e-6);
    }
  EXPECT_EQ (finite, 32 * 32);
}

TEST (ZBufferRangeRenderer, RejectsBadInput)
{
  pcl::ZBufferRangeRenderer renderer;
  EXPECT_THROW (renderer.render (Eigen::Affine3d::Identity ()), pcl::InvalidScanException);
  EXPECT_THROW (renderer.setMesh (pcl::ScanMesh ()), pcl::InvalidScanException);
  pcl::RangeCameraParams camera;
  camera.fov_deg = 180.0;
  EXPECT_THROW (renderer.setCameraParams (camera), pcl::BadArgumentException);
  camera = {};
  camera.width = 0;
  EXPECT_THROW (renderer.setCameraParams (camera), pcl::BadArgumentException);
  camera = {};
  camera.orthographic = true;
  camera.ortho_extent = -1.0;
  EXPECT_THROW (renderer.setCameraParams (camera), pcl::BadArgumentException);
  pcl::ScanMesh bad;
  addSquare (bad, 1.0, 0.0);
  bad.polygons[0].vertices[2] = 99;
  EXPECT_THROW (renderer.setMesh (bad), pcl::InvalidScanException);
  bad.polygons[0].vertices[2] = 2;
  (*bad.cloud)[1].x = std::numeric_limits<float>::quiet_NaN ();
  EXPECT_THROW (renderer.setMesh (bad), pcl::InvalidScanException);
}

// Ground truth on the built-in object (always available): all 26 views lie on the mesh.
TEST (ZBufferRangeRenderer, ExampleObjectViewsLieOnTheMesh)
{
  pcl::ExampleObjectParams params;
  params.subdivisions = 4;
  expectViewsOnMesh (pcl::makeExampleObject (params), pcl::makeDefaultViewDirections (), 120);
}

// Ground truth on the Stanford bunny reconstruction: all 26 views lie on the mesh.
TEST (ZBufferRangeRenderer, BunnyViewsLieOnTheMesh)
{
  PCL_TENSOR_REQUIRE_SHARED_DATA (path, "stanford/bunny/bun_zipper.ply");
  expectViewsOnMesh (pcl::io::loadScanMesh (path), pcl::makeDefaultViewDirections (), 200);
}

// A pushbroom camera sweeps its columns in parallel (x = the column's place on the sensor line) and
// fans each column's rows (y / -z = the row's slope); its view says so, and every hit lies on the sphere.
TEST (ZBufferRangeRenderer, PushbroomColumnsAreParallelAndRowsFanOut)
{
  const double r = 0.1;
  const Eigen::Vector3d centre (0.0, 0.0, -1.0);
  const auto mesh = icosphere (5, r, centre);
  const double sag = maxChordSag (mesh, r);
  pcl::RangeCameraParams camera;
  camera.width = 80;
  camera.height = 60;
  camera.pushbroom = true;
  camera.ortho_extent = 0.25;
  camera.fov_deg = 20.0;
  pcl::ZBufferRangeRenderer renderer;
  renderer.setCameraParams (camera);
  renderer.setMesh (mesh);
  const auto view = renderer.render (Eigen::Affine3d::Identity ());
  EXPECT_EQ (view.viewpoint.model, pcl::ScanViewpoint::Model::pushbroom);
  const double pixel = camera.ortho_extent / camera.width;
  const double f = 0.5 * camera.width / std::tan (0.5 * camera.fov_deg * M_PI / 180.0);
  int finite = 0;
  for (int row = 0; row < camera.height; ++row)
    for (int col = 0; col < camera.width; ++col)
    {
      const auto& p = view.cloud->at (col, row);
      if (!pcl::isXYZFinite (p))
        continue;
      ++finite;
      EXPECT_NEAR (p.x, (col + 0.5 - 0.5 * camera.width) * pixel, 1e-6);
      EXPECT_NEAR (p.y / -p.z, (0.5 * camera.height - row - 0.5) / f, 1e-6);
      const double radial = (p.getVector3fMap ().cast<double> () - centre).norm ();
      EXPECT_LE (radial, r + 1e-6);
      EXPECT_GE (radial, r - sag - 1e-6);
      // The sensor is back along the line of sight, toward the sweep axis.
      const Eigen::Vector3d back = view.viewpoint.towardSensor (p.getVector3fMap ().cast<double> ());
      EXPECT_NEAR (back.x (), 0.0, 1e-9);
      EXPECT_GT (back.z (), 0.0);
    }
  // Columns within r of the axis see the sphere: about 2 r / pixel of the 80.
  int columns = 0;
  for (int col = 0; col < camera.width; ++col)
  {
    bool seen = false;
    for (int row = 0; row < camera.height; ++row)
      seen = seen || pcl::isXYZFinite (view.cloud->at (col, row));
    columns += seen;
  }
  EXPECT_NEAR (columns, 2.0 * r / pixel, 2.0);
  EXPECT_GT (finite, 0);
}

TEST (ZBufferRangeRenderer, OrthographicAndPushbroomTogetherAreRefused)
{
  pcl::RangeCameraParams camera;
  camera.orthographic = camera.pushbroom = true;
  pcl::ZBufferRangeRenderer renderer;
  EXPECT_THROW (renderer.setCameraParams (camera), pcl::BadArgumentException);
}
