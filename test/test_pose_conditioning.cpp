/*
 * pcl_tensor: tests of the conditioning of a registered pose and the rival poses it leaves open.
 */
#include "test_utils.h"

#include <pcl/registration/pose_conditioning.h>

#include <functional>

namespace
{
  using Cloud = pcl::PointCloud<pcl::PointNormal>;

  /** Points p(u, v) on a grid of n x n over [-1, 1]^2 (scaled by \a size), with normals n(p). */
  Cloud
  surface (const std::function<Eigen::Vector3f (float, float)>& point, const std::function<Eigen::Vector3f (const Eigen::Vector3f&)>& normal,
           int n = 41, float size = 0.05f)
  {
    Cloud cloud;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
      {
        const float u = size * (2.0f * i / (n - 1) - 1.0f), v = size * (2.0f * j / (n - 1) - 1.0f);
        pcl::PointNormal p;
        p.getVector3fMap () = point (u, v);
        p.getNormalVector3fMap () = normal (p.getVector3fMap ()).normalized ();
        cloud.push_back (p);
      }
    return cloud;
  }

  pcl::registration::PoseConditioning
  conditioningOnItself (const Cloud& cloud)
  {
    pcl::BoundedNearestSearch search (0.01f);
    search.setInputCloud (cloud);
    return pcl::registration::computePoseConditioning (cloud, cloud, search, Eigen::Matrix4f::Identity (), 0.005);
  }

  /** How many eigenvalues are near zero, relative to the largest. */
  int
  freeMotions (const pcl::registration::PoseConditioning& c)
  {
    int free = 0;
    for (int k = 0; k < 6; ++k)
      free += c.eigenvalues (k) < 1e-6 * c.eigenvalues (5);
    return free;
  }

  Cloud
  cylinder ()
  {
    // Axis along y, radius 0.05: a quarter turn of it, seen from +z.
    return surface ([] (float u, float v) { return Eigen::Vector3f (0.05f * std::sin (10.0f * u), v, 0.05f * std::cos (10.0f * u)); },
                    [] (const Eigen::Vector3f& p) { return Eigen::Vector3f (p.x (), 0.0f, p.z ()); });
  }
}

// A plane leaves three motions free (two slides and the turn about its normal), a cylinder two (the
// slide along and the turn about its axis), a sphere three (every turn about its centre).
TEST (PoseConditioning, FreeMotionsOfPlaneCylinderAndSphere)
{
  const Cloud plane = surface ([] (float u, float v) { return Eigen::Vector3f (u, v, 0.0f); },
                               [] (const Eigen::Vector3f&) { return Eigen::Vector3f::UnitZ (); });
  const Cloud sphere = surface ([] (float u, float v) { return Eigen::Vector3f (u, v, std::sqrt (0.01f - u * u - v * v)); },
                                [] (const Eigen::Vector3f& p) { return p; });
  const auto p = conditioningOnItself (plane), c = conditioningOnItself (cylinder ()), s = conditioningOnItself (sphere);
  EXPECT_EQ (p.pairs, plane.size ());
  EXPECT_EQ (freeMotions (p), 3);
  EXPECT_EQ (freeMotions (c), 2);
  EXPECT_EQ (freeMotions (s), 3);
  for (const auto* r : {&p, &c, &s})
    EXPECT_LT (r->ratio, 1e-6);
  // The plane's patch radius is the RMS distance of its n x n grid over [-a, a]^2 from the centre:
  // E[u^2] = a^2 (n + 1) / (3 (n - 1)) per axis.
  EXPECT_NEAR (p.radius, 0.05 * std::sqrt (2.0 * 42.0 / (3.0 * 40.0)), 1e-6);
}

// A saddle with a ridge pins every motion down.
TEST (PoseConditioning, CurvedPatchWithoutSymmetryIsWellConditioned)
{
  const auto z = [] (float u, float v) { return 10.0f * u * v + 20.0f * u * u * u + 5.0f * v * v; };
  const Cloud patch = surface ([&] (float u, float v) { return Eigen::Vector3f (u, v, z (u, v)); },
                               [] (const Eigen::Vector3f& p) {
                                 const float u = p.x (), v = p.y ();
                                 return Eigen::Vector3f (-(10.0f * v + 60.0f * u * u), -(10.0f * u + 10.0f * v), 1.0f);
                               });
  const auto c = conditioningOnItself (patch);
  EXPECT_EQ (freeMotions (c), 0);
  EXPECT_GT (c.ratio, 1e-4);
  // Moved away from its copy, nothing pairs and nothing is measured.
  pcl::BoundedNearestSearch search (0.01f);
  search.setInputCloud (patch);
  Eigen::Matrix4f far = Eigen::Matrix4f::Identity ();
  far (0, 3) = 1.0f;
  EXPECT_EQ (pcl::registration::computePoseConditioning (patch, patch, search, far, 0.005).pairs, 0u);
  EXPECT_EQ (pcl::registration::computePoseConditioning (patch, patch, search, far, 0.005).ratio, 0.0);
}

// Rival poses: each step and its negative along the least constrained motions, then three half
// turns. On a cylinder the first two motions keep the surface on itself: the rival poses slide
// along it or turn about its axis, and every moved point stays on the cylinder.
TEST (PoseConditioning, RivalPosesFollowTheFreeMotions)
{
  const Cloud cyl = cylinder ();
  const auto c = conditioningOnItself (cyl);
  const auto rivals = pcl::registration::rivalPoses (c, Eigen::Matrix4f::Identity (), 2, {0.35, 0.8});
  ASSERT_EQ (rivals.size (), 2u * 2u * 2u + 3u);
  for (std::size_t k = 0; k < 8; ++k)
  {
    // The smallest step moves the patch's rim by 0.35 of its radius (about 1.5 cm here).
    EXPECT_GT ((rivals[k] - Eigen::Matrix4f::Identity ()).norm (), 0.005f) << "rival " << k << " does not move";
    for (std::size_t i = 0; i < cyl.size (); i += 97)
    {
      const Eigen::Vector3f q = (rivals[k] * cyl[i].getVector4fMap ()).head<3> ();
      EXPECT_NEAR (std::hypot (q.x (), q.z ()), 0.05, 1e-5) << "rival " << k << " leaves the cylinder";
    }
  }
  // The half turns are rotations by 180 degrees about the patch's centroid.
  for (std::size_t k = 8; k < rivals.size (); ++k)
  {
    EXPECT_NEAR ((rivals[k].topLeftCorner<3, 3> ().trace ()), -1.0f, 1e-5);
    const Eigen::Vector3f centroid = c.centroid.cast<float> ();
    EXPECT_LT (((rivals[k] * centroid.homogeneous ()).head<3> () - centroid).norm (), 1e-6f);
  }
  // The steps are motionPoses(), in its order.
  const auto steps = pcl::registration::motionPoses (c, Eigen::Matrix4f::Identity (), 2, {0.35, 0.8});
  ASSERT_EQ (steps.size (), 8u);
  for (std::size_t k = 0; k < steps.size (); ++k)
    EXPECT_TRUE (steps[k].isApprox (rivals[k])) << "step " << k;
  // No pairs, no rivals.
  EXPECT_TRUE (pcl::registration::rivalPoses (pcl::registration::PoseConditioning (), Eigen::Matrix4f::Identity (), 2, {0.35}).empty ());
  EXPECT_TRUE (pcl::registration::motionPoses (pcl::registration::PoseConditioning (), Eigen::Matrix4f::Identity (), 2, {0.35}).empty ());
}

// A cone's patch leaves one motion free, the turn about its axis (y, off the patch's centroid). Turned
// along that screw by 90, 135 and 180 degrees, every point stays on the cone at its own height,
// however far the turn.
TEST (PoseConditioning, RivalTurnsFollowTheScrewOfASurfaceOfRevolution)
{
  const auto radius = [] (float y) { return 0.05f + 0.3f * y; };
  const Cloud cone = surface ([&] (float u, float v) { return Eigen::Vector3f (radius (v) * std::sin (10.0f * u), v, radius (v) * std::cos (10.0f * u)); },
                              [] (const Eigen::Vector3f& p) {
                                const float r = std::hypot (p.x (), p.z ());
                                return Eigen::Vector3f (p.x () / r, -0.3f, p.z () / r);
                              });
  const auto c = conditioningOnItself (cone);
  ASSERT_EQ (freeMotions (c), 1);
  const std::vector<double> turns{0.5 * M_PI, 0.75 * M_PI, M_PI};
  const auto rivals = pcl::registration::screwTurnPoses (c, Eigen::Matrix4f::Identity (), turns);
  ASSERT_EQ (rivals.size (), 5u) << "each turn both ways, a half turn once";
  const double expected[] = {90.0, 90.0, 135.0, 135.0, 180.0};
  for (std::size_t k = 0; k < 5; ++k)
  {
    const Eigen::Matrix4f& t = rivals[k];
    const Eigen::AngleAxisf turn (Eigen::Matrix3f (t.topLeftCorner<3, 3> ()));
    EXPECT_NEAR (turn.angle () * 180.0 / M_PI, expected[k], 1e-3) << "turn " << k;
    EXPECT_NEAR (std::abs (turn.axis ().y ()), 1.0f, 1e-4f) << "turn " << k << " is not about the cone's axis";
    for (std::size_t i = 0; i < cone.size (); i += 97)
    {
      const Eigen::Vector3f q = (t * cone[i].getVector4fMap ()).head<3> ();
      EXPECT_NEAR (q.y (), cone[i].y, 1e-5f) << "turn " << k << " slides along the axis";
      EXPECT_NEAR (std::hypot (q.x (), q.z ()), radius (cone[i].y), 1e-5) << "turn " << k << " leaves the cone";
    }
  }
  // A least constrained motion that does not turn (a plane's slide) has no screw to follow.
  pcl::registration::PoseConditioning slide = c;
  slide.eigenvectors.col (0) << 0.0, 0.0, 0.0, 1.0, 0.0, 0.0;
  EXPECT_TRUE (pcl::registration::screwTurnPoses (slide, Eigen::Matrix4f::Identity (), turns).empty ());
}
