/*
 * pcl_tensor: stray fragments of a scan, on meshes whose fragments are known by construction.
 */
#include <pcl/surface/stray_fragment_removal.h>
#include <pcl/surface/scan_preparation.h>
#include <pcl/common/tensor_exceptions.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

namespace
{
  /** An n x n grid of unit spacing at \a offset, two triangles per cell, appended to \a mesh. */
  void
  appendGrid (pcl::ScanMesh& mesh, int n, const Eigen::Vector3f& offset)
  {
    const auto first = static_cast<pcl::index_t> (mesh.cloud->size ());
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
      {
        pcl::PointNormal p;
        p.getVector3fMap () = offset + Eigen::Vector3f (static_cast<float> (c), static_cast<float> (r), 0.0f);
        p.getNormalVector3fMap () = Eigen::Vector3f::UnitZ ();
        mesh.cloud->push_back (p);
      }
    const auto at = [&] (int r, int c) { return first + static_cast<pcl::index_t> (r * n + c); };
    for (int r = 0; r + 1 < n; ++r)
      for (int c = 0; c + 1 < n; ++c)
      {
        for (const auto& corners : {std::array<pcl::index_t, 3>{at (r, c), at (r, c + 1), at (r + 1, c)},
                                    std::array<pcl::index_t, 3>{at (r, c + 1), at (r + 1, c + 1), at (r + 1, c)}})
        {
          pcl::Vertices triangle;
          triangle.vertices.assign (corners.begin (), corners.end ());
          mesh.polygons.push_back (std::move (triangle));
        }
      }
  }
}

TEST (StrayFragmentRemoval, AFarSmallPatchGoesANearOneAndALargeFarOneStay)
{
  pcl::ScanMesh mesh;
  appendGrid (mesh, 100, Eigen::Vector3f::Zero ());                 // the scan: 10000 points
  appendGrid (mesh, 4, Eigen::Vector3f (300.0f, 0.0f, 0.0f));       // 16 points, 200 units away: stray
  appendGrid (mesh, 4, Eigen::Vector3f (0.0f, 0.0f, 5.0f));         // 16 points, 5 units above: near
  appendGrid (mesh, 40, Eigen::Vector3f (0.0f, 0.0f, -500.0f));     // 1600 points, far but large
  const std::size_t points = mesh.cloud->size ();
  const std::size_t faces = mesh.polygons.size ();

  const auto stray = pcl::strayFragmentPoints (*mesh.cloud, 20.0, 0.01);
  ASSERT_EQ (stray.size (), points);
  for (std::size_t i = 0; i < points; ++i)
    EXPECT_EQ (stray[i], i >= 10000 && i < 10016) << "point " << i;

  EXPECT_EQ (pcl::removeStrayFragments (mesh, 20.0, 0.01), 16u);
  EXPECT_EQ (mesh.cloud->size (), points - 16);
  EXPECT_EQ (mesh.polygons.size (), faces - 18);  // a 4 x 4 grid has 18 triangles
  for (const auto& poly : mesh.polygons)
    for (const auto v : poly.vertices)
    {
      ASSERT_LT (static_cast<std::size_t> (v), mesh.cloud->size ());
      EXPECT_LT ((*mesh.cloud)[v].x, 200.0f);  // nothing of the stray patch is left
    }
}

TEST (StrayFragmentRemoval, GapAndFractionDecide)
{
  pcl::ScanMesh mesh;
  appendGrid (mesh, 100, Eigen::Vector3f::Zero ());
  appendGrid (mesh, 4, Eigen::Vector3f (130.0f, 0.0f, 0.0f));  // 31 units beyond the grid's edge
  // A gap wider than the distance joins the patch to the scan; a fraction of 0 keeps everything.
  EXPECT_EQ (pcl::removeStrayFragments (mesh, 40.0, 0.01), 0u);
  EXPECT_EQ (pcl::removeStrayFragments (mesh, 10.0, 0.0), 0u);
  // A fraction under the patch's share (16 of 10016) keeps it too.
  EXPECT_EQ (pcl::removeStrayFragments (mesh, 10.0, 0.001), 0u);
  EXPECT_EQ (pcl::removeStrayFragments (mesh, 10.0, 0.01), 16u);
}

TEST (StrayFragmentRemoval, TheLargestGroupAndNaNPointsAreNeverStray)
{
  pcl::PointCloud<pcl::PointNormal> scattered;
  for (int i = 0; i < 200; ++i)
  {
    pcl::PointNormal p;
    p.getVector3fMap () = Eigen::Vector3f (100.0f * static_cast<float> (i), 0.0f, 0.0f);
    scattered.push_back (p);
  }
  scattered[7].x = std::numeric_limits<float>::quiet_NaN ();
  const auto stray = pcl::strayFragmentPoints (scattered, 1.0, 0.5);
  // 199 groups of one point, each under half: all stray but the one largest (the first found).
  EXPECT_EQ (std::count (stray.begin (), stray.end (), true), 198);
  EXPECT_FALSE (stray[7]);
}

TEST (StrayFragmentRemoval, FarFromTheOriginTheCellsKeepTheirDigits)
{
  pcl::ScanMesh mesh;
  appendGrid (mesh, 100, Eigen::Vector3f (1e6f, -2e6f, 5e5f));
  appendGrid (mesh, 3, Eigen::Vector3f (1e6f + 400.0f, -2e6f, 5e5f));
  EXPECT_EQ (pcl::removeStrayFragments (mesh, 20.0, 0.01), 9u);
}

TEST (StrayFragmentRemoval, BadArgumentsAreRefused)
{
  pcl::PointCloud<pcl::PointNormal> cloud;
  cloud.push_back (pcl::PointNormal ());
  EXPECT_THROW (pcl::strayFragmentPoints (cloud, 0.0, 0.01), pcl::BadArgumentException);
  EXPECT_THROW (pcl::strayFragmentPoints (cloud, std::numeric_limits<double>::infinity (), 0.01), pcl::BadArgumentException);
  EXPECT_THROW (pcl::strayFragmentPoints (cloud, 1.0, 1.0), pcl::BadArgumentException);
  EXPECT_THROW (pcl::strayFragmentPoints (cloud, 1.0, -0.1), pcl::BadArgumentException);
  pcl::ScanPreparationParams params;
  params.stray_fragment_fraction = 1.0;
  EXPECT_THROW (pcl::checkScanPreparationParams (params), pcl::BadArgumentException);
  params.stray_fragment_fraction = 0.01;
  params.stray_fragment_gap = -1.0;
  EXPECT_THROW (pcl::checkScanPreparationParams (params), pcl::BadArgumentException);
}
