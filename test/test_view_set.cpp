/*
 * pcl_tensor: tests of the view sets (Sections 6 and 7.1: 26 views 30 degrees apart).
 */
#include "test_utils.h"

#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/simulation/example_object.h>
#include <pcl/simulation/view_set.h>

namespace
{
  double
  angleDeg (const Eigen::Vector3d& a, const Eigen::Vector3d& b)
  {
    return std::acos (std::clamp (a.dot (b), -1.0, 1.0)) * 180.0 / M_PI;
  }
}

TEST (ViewSet, DefaultSetHas26UnitDirectionsOnThreeRingsAndTwoPoles)
{
  const auto d = pcl::makeDefaultViewDirections ();
  ASSERT_EQ (d.size (), 26u);
  int equator = 0, north = 0, south = 0;
  for (const auto& v : d)
  {
    EXPECT_NEAR (v.norm (), 1.0, 1e-12);
    const double elevation = 90.0 - angleDeg (v, Eigen::Vector3d::UnitY ());
    equator += std::abs (elevation) < 1e-9 ? 1 : 0;
    north += std::abs (elevation - 60.0) < 1e-9 ? 1 : 0;
    south += std::abs (elevation + 60.0) < 1e-9 ? 1 : 0;
  }
  EXPECT_EQ (equator, 12);
  EXPECT_EQ (north, 6);
  EXPECT_EQ (south, 6);
  EXPECT_NEAR (angleDeg (d[24], Eigen::Vector3d::UnitY ()), 0.0, 1e-9);
  EXPECT_NEAR (angleDeg (d[25], -Eigen::Vector3d::UnitY ()), 0.0, 1e-9);
  for (std::size_t i = 0; i < d.size (); ++i)
    for (std::size_t j = i + 1; j < d.size (); ++j)
      EXPECT_GT (angleDeg (d[i], d[j]), 28.0) << i << " " << j;  // no two views coincide
}

// Every view has a neighbour about 30 degrees away: equator views have 2 (exactly 30), ring views have
// 2 ring neighbours (28.96 degrees) and their pole (30), poles have their 6 ring views.
TEST (ViewSet, NeighboursAreAbout30DegreesApart)
{
  const auto d = pcl::makeDefaultViewDirections ();
  const auto nb = pcl::viewNeighbours (d);
  ASSERT_EQ (nb.size (), 26u);
  for (int i = 0; i < 12; ++i)
  {
    ASSERT_EQ (nb[i].size (), 2u) << i;
    for (int j : nb[i])
      EXPECT_NEAR (angleDeg (d[i], d[j]), 30.0, 1e-9);
  }
  for (int i = 12; i < 24; ++i)
    EXPECT_EQ (nb[i].size (), 3u) << i;
  EXPECT_EQ (nb[24].size (), 6u);
  EXPECT_EQ (nb[25].size (), 6u);
  const auto pairs = pcl::adjacentViewPairs (d);
  EXPECT_EQ (pairs.size (), 12u + 2u * (6u + 6u));
  for (const auto& p : pairs)
  {
    EXPECT_LT (p.first, p.second);
    EXPECT_LE (std::abs (angleDeg (d[p.first], d[p.second]) - 30.0), 2.0);
  }
}

TEST (ViewSet, RingIsATurntable)
{
  const auto d = pcl::makeRingViewDirections (15, 24.0);
  ASSERT_EQ (d.size (), 15u);
  for (std::size_t i = 0; i + 1 < d.size (); ++i)
  {
    EXPECT_NEAR (angleDeg (d[i], d[i + 1]), 24.0, 1e-9);
    EXPECT_NEAR (d[i].y (), 0.0, 1e-12);
  }
  EXPECT_EQ (pcl::adjacentViewPairs (d, 24.0, 1.0).size (), 15u);  // a closed ring
  EXPECT_THROW (pcl::makeRingViewDirections (0, 30.0), pcl::BadArgumentException);
  EXPECT_THROW (pcl::makeRingViewDirections (4, 30.0, 90.0), pcl::BadArgumentException);
}

// Each sensor sits on its direction at the given distance, looks at the centre down its -z axis,
// and keeps its y axis in the plane of the up vector.
TEST (ViewSet, LookAtPosesLookAtTheCentre)
{
  pcl::ViewTarget target;
  target.centre = Eigen::Vector3d (0.1, 0.2, -0.3);
  target.radius = 0.5;
  const auto d = pcl::makeDefaultViewDirections ();
  const auto poses = pcl::lookAtPoses (d, target, 2.0);
  ASSERT_EQ (poses.size (), d.size ());
  for (std::size_t i = 0; i < poses.size (); ++i)
  {
    EXPECT_TRUE ((poses[i].linear () * poses[i].linear ().transpose ()).isIdentity (1e-12));
    EXPECT_NEAR (poses[i].linear ().determinant (), 1.0, 1e-12);
    EXPECT_TRUE ((poses[i].inverse () * target.centre).isApprox (Eigen::Vector3d (0, 0, -2.0), 1e-12)) << i;
    EXPECT_TRUE ((poses[i].translation () - target.centre).isApprox (2.0 * d[i], 1e-12)) << i;
  }
}

// The fitted distance keeps the object inside the image: the image border stays empty.
TEST (ViewSet, FittingDistanceKeepsTheObjectInView)
{
  pcl::ExampleObjectParams params;
  params.subdivisions = 3;
  const auto mesh = pcl::makeExampleObject (params);
  pcl::RangeCameraParams camera;
  camera.width = 80;
  camera.height = 60;
  const auto target = pcl::boundingTarget (mesh);
  const double distance = pcl::fittingDistance (target, camera);
  EXPECT_GT (distance, target.radius);
  pcl::ZBufferRangeRenderer renderer;
  renderer.setMesh (mesh);
  renderer.setCameraParams (camera);
  for (const auto& pose : pcl::lookAtPoses (pcl::makeDefaultViewDirections (), target, distance))
  {
    const auto view = renderer.render (pose);
    int border = 0, finite = 0;
    for (int r = 0; r < camera.height; ++r)
      for (int c = 0; c < camera.width; ++c)
      {
        const bool f = pcl::isXYZFinite (view.cloud->at (c, r));
        finite += f ? 1 : 0;
        border += (f && (r == 0 || c == 0 || r == camera.height - 1 || c == camera.width - 1)) ? 1 : 0;
      }
    EXPECT_EQ (border, 0);
    EXPECT_GT (finite, camera.width * camera.height / 10);
  }
  EXPECT_THROW (pcl::fittingDistance (pcl::ViewTarget (), camera), pcl::BadArgumentException);
}
