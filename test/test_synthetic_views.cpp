/*
 * pcl_tensor: tests of the synthetic view sets (Sections 6, 7.1 and 7.5).
 */
#include "test_utils.h"

#include <pcl/common/point_mesh_distance.h>
#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/simulation/example_object.h>
#include <pcl/io/range_grid_ply.h>
#include <pcl/io/range_scan_io.h>
#include <pcl/io/stanford_conf.h>
#include <pcl/simulation/synthetic_views.h>

#include <cstdio>

namespace
{
  pcl::ScanMesh
  smallObject ()
  {
    pcl::ExampleObjectParams params;
    params.subdivisions = 4;
    return pcl::makeExampleObject (params);
  }

  pcl::SyntheticViewParams
  smallCamera ()
  {
    pcl::SyntheticViewParams params;
    params.camera.width = params.camera.height = 120;
    return params;
  }
}

// Clean views lie on the model and carry a resolution of the order of the pixel footprint.
TEST (SyntheticViews, CleanViewsLieOnTheModel)
{
  const auto model = smallObject ();
  const auto views = pcl::renderSyntheticViews (model, pcl::makeRingViewDirections (4, 90.0), smallCamera ());
  ASSERT_EQ (views.size (), 4u);
  pcl::PointMeshDistance distance;
  distance.setMesh (model);
  const double size = 2.0 * pcl::boundingTarget (model).radius;
  for (const auto& v : views)
  {
    EXPECT_GT (v.resolution, 0.0);
    EXPECT_LT (v.resolution, size / 20.0);
    for (const auto& p : *v.view.cloud)
    {
      if (pcl::isXYZFinite (p))
      {
        ASSERT_LE (distance.distance (v.view.pose * p.getVector3fMap ().cast<double> ()), 1e-6 * size);
      }
    }
  }
}

// Section 7.5: sigma is given in units of each view's d_res; measure it back along the rays.
TEST (SyntheticViews, NoiseSigmaIsInResolutions)
{
  const auto model = smallObject ();
  const auto directions = pcl::makeRingViewDirections (2, 180.0);
  auto params = smallCamera ();
  const auto clean = pcl::renderSyntheticViews (model, directions, params);
  params.noise_sigma_resolutions = 2.0;
  params.seed = 9;
  const auto noisy = pcl::renderSyntheticViews (model, directions, params);
  ASSERT_EQ (noisy.size (), clean.size ());
  for (std::size_t v = 0; v < clean.size (); ++v)
  {
    EXPECT_EQ (noisy[v].resolution, clean[v].resolution);  // the resolution is the clean view's
    double sum = 0.0, sq = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < clean[v].view.cloud->size (); ++i)
    {
      const auto& c = (*clean[v].view.cloud)[i];
      if (!pcl::isXYZFinite (c))
        continue;
      const Eigen::Vector3d p = c.getVector3fMap ().cast<double> ();
      const Eigen::Vector3d q = (*noisy[v].view.cloud)[i].getVector3fMap ().cast<double> ();
      const double r = q.norm () - p.norm ();  // perspective rays start at the sensor's origin
      sum += r;
      sq += r * r;
      ++n;
    }
    const double mean = sum / n;
    const double sigma = std::sqrt (sq / n - mean * mean);
    EXPECT_NEAR (sigma, 2.0 * clean[v].resolution, 0.05 * 2.0 * clean[v].resolution) << "view " << v;
  }
}

TEST (SyntheticViews, SameSeedSameViews)
{
  const auto model = smallObject ();
  auto params = smallCamera ();
  params.noise_sigma_resolutions = 1.0;
  const auto d = pcl::makeRingViewDirections (2, 90.0);
  const auto a = pcl::renderSyntheticViews (model, d, params);
  const auto b = pcl::renderSyntheticViews (model, d, params);
  for (std::size_t v = 0; v < a.size (); ++v)
    for (std::size_t i = 0; i < a[v].view.cloud->size (); ++i)
    {
      if (pcl::isXYZFinite ((*a[v].view.cloud)[i]))
      {
        ASSERT_EQ ((*a[v].view.cloud)[i].getVector3fMap (), (*b[v].view.cloud)[i].getVector3fMap ());
      }
    }
  params.noise_sigma_resolutions = -1.0;
  EXPECT_THROW (pcl::renderSyntheticViews (model, d, params), pcl::BadArgumentException);
}

// End to end, as the app does it: range_grid PLY files plus a .conf, read back with the project's
// loaders, put every point back on the model (this checks the R(q)^T convention of the written poses).
TEST (SyntheticViews, FilesAndConfReproduceTheGroundTruth)
{
  const auto model = smallObject ();
  const auto views = pcl::renderSyntheticViews (model, pcl::makeDefaultViewDirections (), smallCamera ());
  std::vector<pcl::io::StanfordConfEntry> entries;
  const std::string dir = ::testing::TempDir ();
  for (std::size_t i = 0; i < views.size (); i += 5)
  {
    const std::string name = "synthetic_view_" + std::to_string (i) + ".ply";
    pcl::io::saveRangeGridPLY (dir + name, *views[i].view.cloud);
    entries.push_back (pcl::io::StanfordConfEntry::fromPose (name, views[i].view.pose));
  }
  pcl::io::saveStanfordConf (dir + "synthetic_views.conf", entries);
  pcl::PointMeshDistance distance;
  distance.setMesh (model);
  const double size = 2.0 * pcl::boundingTarget (model).radius;
  for (const auto& e : pcl::io::loadStanfordConf (dir + "synthetic_views.conf"))
  {
    const auto scan = pcl::io::loadRangeScan (dir + e.file);
    double worst = 0.0;
    for (const auto& p : *scan.cloud)
      if (pcl::isXYZFinite (p))
        worst = std::max (worst, distance.distance (e.pose () * p.getVector3fMap ().cast<double> ()));
    EXPECT_LE (worst, 1e-6 * size) << e.file;
    EXPECT_GT (scan.finite_points, 1000u);
    std::remove ((dir + e.file).c_str ());
  }
  std::remove ((dir + "synthetic_views.conf").c_str ());
}
