/*
 * pcl_tensor: tests of pcl::addScannerArtifacts (grazing dropout, holes, specks) on known renderings.
 */
#include "test_utils.h"

#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/simulation/scanner_artifacts.h>

#include <cmath>

namespace
{
  /** A square of half-size \a h at depth 1 in front of the camera, turned by \a tilt_deg about y. */
  pcl::ScanMesh
  tiltedSquare (double h, double tilt_deg)
  {
    const Eigen::Affine3d place = Eigen::Translation3d (0.0, 0.0, -1.0) * Eigen::AngleAxisd (tilt_deg * M_PI / 180.0, Eigen::Vector3d::UnitY ());
    pcl::ScanMesh mesh;
    for (const auto& xy : {Eigen::Vector2d (-h, -h), Eigen::Vector2d (h, -h), Eigen::Vector2d (h, h), Eigen::Vector2d (-h, h)})
    {
      pcl::PointNormal p;
      p.getVector3fMap () = (place * Eigen::Vector3d (xy.x (), xy.y (), 0.0)).cast<float> ();
      mesh.cloud->push_back (p);
    }
    pcl::Vertices t1, t2;
    t1.vertices = {0, 1, 2};
    t2.vertices = {0, 2, 3};
    mesh.polygons = {t1, t2};
    return mesh;
  }

  pcl::RenderedView
  render (const pcl::ScanMesh& mesh, bool orthographic)
  {
    pcl::RangeCameraParams camera;
    camera.width = camera.height = 120;
    camera.orthographic = orthographic;
    camera.ortho_extent = 0.5;
    camera.fov_deg = 30.0;
    pcl::ZBufferRangeRenderer renderer;
    renderer.setMesh (mesh);
    renderer.setCameraParams (camera);
    return renderer.render (Eigen::Affine3d::Identity ());
  }

  std::size_t
  finiteCount (const pcl::PointCloud<pcl::PointXYZ>& cloud)
  {
    std::size_t n = 0;
    for (const auto& p : cloud)
      n += pcl::isXYZFinite (p);
    return n;
  }

  /** A copy of \a view with its own cloud. */
  pcl::RenderedView
  copyOf (const pcl::RenderedView& view)
  {
    pcl::RenderedView copy = view;
    copy.cloud.reset (new pcl::PointCloud<pcl::PointXYZ> (*view.cloud));
    return copy;
  }
}

TEST (ScannerArtifacts, DefaultsChangeNothingAndDrawNothing)
{
  const auto clean = render (tiltedSquare (1.0, 20.0), false);
  auto view = copyOf (clean);
  std::mt19937 rng (3), untouched (3);
  pcl::addScannerArtifacts (view, pcl::ScannerArtifactParams (), rng);
  ASSERT_EQ (view.cloud->size (), clean.cloud->size ());
  for (std::size_t i = 0; i < clean.cloud->size (); ++i)
  {
    if (pcl::isXYZFinite ((*clean.cloud)[i]))
    {
      EXPECT_EQ ((*view.cloud)[i].getVector3fMap (), (*clean.cloud)[i].getVector3fMap ()) << "pixel " << i;
    }
  }
  EXPECT_EQ (rng (), untouched ());
  EXPECT_TRUE (view.cloud->is_dense);  // the square fills the image
}

// Seen orthographically, a plane turned by a from the line of sight is seen at a everywhere: nothing
// drops below the ramp's start, and (a - start) / (90 - start) of the points drop above it.
TEST (ScannerArtifacts, GrazingSurfacesDropOutAtTheRampsRate)
{
  pcl::ScannerArtifactParams params;
  params.dropout_start_deg = 70.0;
  for (const double tilt : {30.0, 65.0, 80.0})
  {
    auto view = render (tiltedSquare (2.0, tilt), true);
    const double before = static_cast<double> (finiteCount (*view.cloud));
    ASSERT_GT (before, 5000.0);
    std::mt19937 rng (11);
    pcl::addScannerArtifacts (view, params, rng);
    const double dropped = 1.0 - static_cast<double> (finiteCount (*view.cloud)) / before;
    const double expected = std::max (0.0, (tilt - 70.0) / 20.0);
    EXPECT_NEAR (dropped, expected, 0.03) << "tilt " << tilt;
    EXPECT_EQ (view.cloud->is_dense, dropped == 0.0);
  }
}

TEST (ScannerArtifacts, HolesAreDiscsOfAboutTheirRadius)
{
  const auto clean = render (tiltedSquare (1.0, 0.0), false);
  pcl::ScannerArtifactParams params;
  params.holes = 1;
  params.hole_radius_pixels = 6.0;
  for (std::uint32_t seed = 1; seed <= 5; ++seed)
  {
    auto view = copyOf (clean);
    std::mt19937 rng (seed);
    pcl::addScannerArtifacts (view, params, rng);
    Eigen::Vector2d sum = Eigen::Vector2d::Zero ();
    std::vector<Eigen::Vector2d> emptied;
    for (int row = 0; row < 120; ++row)
      for (int col = 0; col < 120; ++col)
        if (!pcl::isXYZFinite (view.cloud->at (col, row)))
        {
          emptied.emplace_back (col, row);
          sum += emptied.back ();
        }
    ASSERT_FALSE (emptied.empty ()) << "seed " << seed;
    // A radius between 3 and 9 pixels: the disc's area, unless it is cut by the image border.
    EXPECT_LE (emptied.size (), static_cast<std::size_t> (M_PI * 9.5 * 9.5)) << "seed " << seed;
    EXPECT_GE (emptied.size (), 9u) << "seed " << seed;
    const Eigen::Vector2d centre = sum / static_cast<double> (emptied.size ());
    for (const auto& p : emptied)
      EXPECT_LE ((p - centre).norm (), 2.0 * 9.0 + 1.0) << "seed " << seed;
  }
}

// A speck replaces surface pixels by points on the same lines of sight, 5% to 50% of the depth nearer.
TEST (ScannerArtifacts, SpecksLieOnTheirLinesOfSightInFrontOfTheSurface)
{
  const auto clean = render (tiltedSquare (1.0, 0.0), false);
  auto view = copyOf (clean);
  pcl::ScannerArtifactParams params;
  params.specks = 10;
  params.speck_pixels = 3;
  std::mt19937 rng (5);
  pcl::addScannerArtifacts (view, params, rng);
  int moved = 0;
  for (std::size_t i = 0; i < clean.cloud->size (); ++i)
  {
    const Eigen::Vector3f a = (*clean.cloud)[i].getVector3fMap (), b = (*view.cloud)[i].getVector3fMap ();
    if (a == b)
      continue;
    ++moved;
    EXPECT_LT (a.normalized ().cross (b.normalized ()).norm (), 1e-5f) << "pixel " << i;  // same ray from the centre
    const float nearer = 1.0f - b.z () / a.z ();
    EXPECT_GE (nearer, 0.05f - 1e-5f);
    EXPECT_LE (nearer, 0.5f + 1e-5f);
  }
  EXPECT_GE (moved, 5);  // ten specks, of which two could share a pixel
  EXPECT_LE (moved, 30);
  EXPECT_EQ (finiteCount (*view.cloud), finiteCount (*clean.cloud));
}

TEST (ScannerArtifacts, BadParametersAreRefused)
{
  auto view = render (tiltedSquare (1.0, 0.0), false);
  std::mt19937 rng (1);
  pcl::ScannerArtifactParams p;
  p.dropout_start_deg = 91.0;
  EXPECT_THROW (pcl::addScannerArtifacts (view, p, rng), pcl::BadArgumentException);
  p = pcl::ScannerArtifactParams ();
  p.holes = -1;
  EXPECT_THROW (pcl::addScannerArtifacts (view, p, rng), pcl::BadArgumentException);
  p = pcl::ScannerArtifactParams ();
  p.speck_pixels = 0;
  EXPECT_THROW (pcl::addScannerArtifacts (view, p, rng), pcl::BadArgumentException);
  p = pcl::ScannerArtifactParams ();
  view.cloud->width = static_cast<std::uint32_t> (view.cloud->size ());
  view.cloud->height = 1;
  EXPECT_THROW (pcl::addScannerArtifacts (view, p, rng), pcl::BadArgumentException);
}
