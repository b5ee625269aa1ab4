/*
 * pcl_tensor: tests of the viewing-direction noise (Section 7.5).
 */
#include "test_utils.h"

#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/simulation/example_object.h>
#include <pcl/simulation/range_noise.h>
#include <pcl/simulation/view_set.h>

namespace
{
  pcl::RenderedView
  renderExample (bool orthographic)
  {
    pcl::ExampleObjectParams params;
    params.subdivisions = 4;
    const auto mesh = pcl::makeExampleObject (params);
    pcl::RangeCameraParams camera;
    camera.width = camera.height = 160;
    camera.orthographic = orthographic;
    const auto target = pcl::boundingTarget (mesh);
    camera.ortho_extent = pcl::fittingOrthoExtent (target, camera);
    pcl::ZBufferRangeRenderer renderer;
    renderer.setMesh (mesh);
    renderer.setCameraParams (camera);
    const auto d = pcl::makeDefaultViewDirections ();
    return renderer.render (pcl::lookAtPoses ({d[0]}, target, pcl::fittingDistance (target, camera))[0]);
  }

  /** Signed displacements along the line of sight; also checks that points stay on their ray. */
  std::vector<double>
  residualsAlongRays (const pcl::RenderedView& clean, const pcl::PointCloud<pcl::PointXYZ>& noisy)
  {
    std::vector<double> res;
    for (std::size_t i = 0; i < noisy.size (); ++i)
    {
      const bool f = pcl::isXYZFinite (clean.cloud->points[i]);
      EXPECT_EQ (f, pcl::isXYZFinite (noisy[i])) << "NaN pattern changed at " << i;
      if (!f)
        continue;
      const Eigen::Vector3d p = clean.cloud->points[i].getVector3fMap ().cast<double> ();
      const Eigen::Vector3d q = noisy[i].getVector3fMap ().cast<double> ();
      const Eigen::Vector3d ray = -clean.viewpoint.towardSensor (p);
      const double along = (q - p).dot (ray);
      EXPECT_LE (((q - p) - along * ray).norm (), 1e-6) << "point left its ray at " << i;
      res.push_back (along);
    }
    return res;
  }

  void
  expectSigma (bool orthographic)
  {
    const auto clean = renderExample (orthographic);
    const double sigma = 0.002;
    pcl::PointCloud<pcl::PointXYZ> noisy = *clean.cloud;
    std::mt19937 rng (7);
    pcl::addViewingDirectionNoise (noisy, clean.viewpoint, sigma, rng);
    const auto res = residualsAlongRays (clean, noisy);
    ASSERT_GT (res.size (), 5000u);
    double mean = 0.0, sq = 0.0;
    for (double r : res)
      mean += r;
    mean /= res.size ();
    for (double r : res)
      sq += (r - mean) * (r - mean);
    const double measured = std::sqrt (sq / (res.size () - 1));
    EXPECT_NEAR (measured, sigma, 0.05 * sigma);
    EXPECT_LT (std::abs (mean), 5.0 * sigma / std::sqrt (static_cast<double> (res.size ())));
  }
}

TEST (RangeNoise, PerspectiveSigmaIsMeasuredBack)
{
  expectSigma (false);
}

TEST (RangeNoise, OrthographicSigmaIsMeasuredBack)
{
  expectSigma (true);
}

TEST (RangeNoise, SeededAndRepeatable)
{
  const auto clean = renderExample (false);
  auto a = *clean.cloud, b = *clean.cloud, c = *clean.cloud;
  std::mt19937 ra (1), rb (1), rc (2);
  pcl::addViewingDirectionNoise (a, clean.viewpoint, 0.001, ra);
  pcl::addViewingDirectionNoise (b, clean.viewpoint, 0.001, rb);
  pcl::addViewingDirectionNoise (c, clean.viewpoint, 0.001, rc);
  int same_ab = 0, same_ac = 0, finite = 0;
  for (std::size_t i = 0; i < a.size (); ++i)
    if (pcl::isXYZFinite (a[i]))
    {
      ++finite;
      same_ab += a[i].getVector3fMap () == b[i].getVector3fMap () ? 1 : 0;
      same_ac += a[i].getVector3fMap () == c[i].getVector3fMap () ? 1 : 0;
    }
  EXPECT_EQ (same_ab, finite);
  EXPECT_LT (same_ac, finite / 100);
}

TEST (RangeNoise, RejectsNegativeSigma)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::mt19937 rng (1);
  EXPECT_THROW (pcl::addViewingDirectionNoise (cloud, pcl::ScanViewpoint (), -1.0, rng), pcl::BadArgumentException);
}
