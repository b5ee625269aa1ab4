#include "test_utils.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/registration/global_verification.h>
#include <cmath>
#include <random>

namespace
{
  using pcl::registration::GlobalVerification;

  /** A flat plate of width x height on a regular grid of \a pitch, in the z = 0 plane. */
  pcl::PointCloud<pcl::PointNormal>
  plate (double width, double height, double pitch)
  {
    pcl::PointCloud<pcl::PointNormal> cloud;
    for (double x = 0.0; x <= width + 1e-9; x += pitch)
      for (double y = 0.0; y <= height + 1e-9; y += pitch)
      {
        pcl::PointNormal p;
        p.x = static_cast<float> (x);
        p.y = static_cast<float> (y);
        p.z = 0.0f;
        cloud.push_back (p);
      }
    return cloud;
  }

  Eigen::Affine3d
  shiftX (double dx)
  {
    return Eigen::Affine3d (Eigen::Translation3d (dx, 0.0, 0.0));
  }
}

TEST (GlobalVerification, ExcessIsTheGrowthOfTheCombinedExtents)
{
  // Two copies of a 0.2 x 0.1 plate, the second shifted along its length: the union stays symmetric,
  // so its principal axes are the plate's and its length grows by exactly the shift.
  const double d_res = 0.001;
  const auto view = plate (0.2, 0.1, 0.005);
  const pcl::ObjectDimensions dims = pcl::computeObjectDimensions<pcl::PointNormal> ({&view});
  EXPECT_NEAR (dims.D.x (), 0.2, 1e-6);
  EXPECT_NEAR (dims.D.y (), 0.1, 1e-6);

  GlobalVerification verification (dims, d_res);
  verification.addView (view, Eigen::Affine3d::Identity ());
  EXPECT_NEAR (verification.excess (view, Eigen::Affine3d::Identity ()), 0.0, 1e-3);
  EXPECT_NEAR (verification.excess (view, shiftX (0.003)), 3.0, 1e-3);
  EXPECT_TRUE (verification.accepts (view, shiftX (0.003)));
  EXPECT_NEAR (verification.excess (view, shiftX (0.010)), 10.0, 1e-3);
  EXPECT_FALSE (verification.accepts (view, shiftX (0.010))) << "10 d_res beyond D passed the 4 d_res tolerance";
}

TEST (GlobalVerification, EveryRegisteredViewCounts)
{
  // Each of three plates, placed end to end, passes with the first alone; the third, once the second
  // is registered, makes the whole 0.3 long against D = 0.2 (Section 4.2: all views so far).
  const double d_res = 0.001;
  const auto view = plate (0.1, 0.1, 0.005);
  pcl::ObjectDimensions dims;
  dims.D = Eigen::Vector3d (0.2, 0.1, 0.0);
  GlobalVerification verification (dims, d_res);
  verification.addView (view, Eigen::Affine3d::Identity ());
  EXPECT_TRUE (verification.accepts (view, shiftX (0.1)));
  verification.addView (view, shiftX (0.1));
  EXPECT_TRUE (verification.accepts (view, shiftX (0.05)));
  EXPECT_NEAR (verification.excess (view, shiftX (0.2)), 100.0, 0.5);
  EXPECT_FALSE (verification.accepts (view, shiftX (0.2)));
}

TEST (GlobalVerification, RefusesBadSettings)
{
  pcl::ObjectDimensions dims;
  EXPECT_THROW (GlobalVerification (dims, 0.0), pcl::BadArgumentException);
  pcl::registration::GlobalVerificationParams params;
  params.tolerance = -1.0;
  EXPECT_THROW (GlobalVerification (dims, 0.001, params), pcl::BadArgumentException);
}

namespace
{
  /** A curved patch (part of a sphere of radius 0.1 around \a centre) of n random points, fixed seed. */
  pcl::PointCloud<pcl::PointNormal>
  patch (const Eigen::Vector3d& centre, double spread, int n, unsigned seed)
  {
    std::mt19937 rng (seed);
    std::uniform_real_distribution<double> u (-spread, spread);
    pcl::PointCloud<pcl::PointNormal> cloud;
    for (int i = 0; i < n; ++i)
    {
      const Eigen::Vector3d dir = (Eigen::Vector3d (u (rng), u (rng), 1.0)).normalized ();
      pcl::PointNormal p;
      p.getVector3fMap () = (centre + 0.1 * dir).cast<float> ();
      cloud.push_back (p);
    }
    return cloud;
  }

  Eigen::Affine3d
  randomPose (std::mt19937& rng)
  {
    std::uniform_real_distribution<double> u (-1.0, 1.0);
    const Eigen::Quaterniond q = Eigen::Quaterniond (u (rng), u (rng), u (rng), u (rng)).normalized ();
    return Eigen::Translation3d (0.02 * u (rng), 0.02 * u (rng), 0.02 * u (rng)) * q;
  }
}

TEST (GlobalVerification, ExcessEqualsTheDirectComputationOverAllPoints)
{
  // The running extents and merged moments must give registeredDimensionExcess over all the points.
  std::mt19937 rng (7);
  pcl::ObjectDimensions dims;
  dims.D = Eigen::Vector3d (0.12, 0.1, 0.05);
  const double d_res = 0.001;
  GlobalVerification verification (dims, d_res);
  std::vector<Eigen::Vector3d> points;
  std::vector<std::size_t> starts;
  for (int v = 0; v < 6; ++v)
  {
    const auto view = patch (Eigen::Vector3d (0.0, 0.0, -0.1), 0.4 + 0.1 * v, 300 + 50 * v, 100 + v);
    const Eigen::Affine3d pose = randomPose (rng);
    std::vector<Eigen::Vector3d> with = points;
    std::vector<std::size_t> with_starts = starts;
    with_starts.push_back (with.size ());
    for (const auto& p : view)
      with.push_back (pose * p.getVector3fMap ().cast<double> ());
    const double direct = pcl::registeredDimensionExcess (with, with_starts, dims, 2) / d_res;
    EXPECT_NEAR (verification.excess (view, pose), direct, 1e-3) << "view " << v << " (points kept as floats)";
    verification.addView (view, pose);
    points = with;
    starts = with_starts;
  }
  EXPECT_EQ (verification.views (), 6u);
  // A cap of a sphere is its own convex hull's boundary: every point is kept.
  EXPECT_EQ (verification.size (), points.size ());
}

TEST (GlobalVerification, AViewKeepsTheVerticesOfItsConvexHull)
{
  // A plate with a bump: the points inside the plate's outline are not on the hull, and are not kept;
  // the extents are the plate's, as over all points.
  auto view = plate (0.2, 0.1, 0.005);
  for (auto& p : view)
    p.z = static_cast<float> (0.01 * std::exp (-((p.x - 0.1) * (p.x - 0.1) + (p.y - 0.05) * (p.y - 0.05)) / 0.001));
  pcl::ObjectDimensions dims;
  dims.D = Eigen::Vector3d (0.2, 0.1, 0.01);
  GlobalVerification verification (dims, 0.001);
  verification.addView (view, Eigen::Affine3d::Identity ());
  EXPECT_LT (verification.size (), view.size () / 2);
  EXPECT_GT (verification.size (), 4u);
  EXPECT_NEAR (verification.excess (view, shiftX (0.003)), 3.0, 1e-3);
}

TEST (GlobalVerification, MergingGroupsEqualsAddingTheirViewsOneByOne)
{
  std::mt19937 rng (11);
  pcl::ObjectDimensions dims;
  dims.D = Eigen::Vector3d (0.12, 0.1, 0.05);
  const double d_res = 0.001;
  GlobalVerification a (dims, d_res), b (dims, d_res), all (dims, d_res);
  std::vector<pcl::PointCloud<pcl::PointNormal>> views;
  std::vector<Eigen::Affine3d, Eigen::aligned_allocator<Eigen::Affine3d>> poses;
  for (int v = 0; v < 5; ++v)
  {
    views.push_back (patch (Eigen::Vector3d (0.0, 0.0, -0.1), 0.5, 200, 200 + v));
    poses.push_back (randomPose (rng));
  }
  const Eigen::Affine3d b_to_a = randomPose (rng);
  for (int v = 0; v < 2; ++v)
    a.addView (views[v], poses[v]);
  for (int v = 2; v < 5; ++v)
    b.addView (views[v], poses[v]);
  for (int v = 0; v < 5; ++v)
    all.addView (views[v], v < 2 ? poses[v] : b_to_a * poses[v]);
  const auto probe = patch (Eigen::Vector3d (0.0, 0.0, -0.1), 0.3, 150, 999);
  const double expected = all.excess (probe, Eigen::Affine3d::Identity ());
  GlobalVerification single (dims, d_res);
  single.addView (probe, Eigen::Affine3d::Identity ());
  // The union checked as a group, from either side, then merged.
  GlobalVerification merged = a;
  merged.merge (b, b_to_a);
  EXPECT_NEAR (merged.excess (probe, Eigen::Affine3d::Identity ()), expected, 1e-3);
  EXPECT_NEAR (a.excess (b, b_to_a), b.excess (a, b_to_a.inverse ()), 1e-3);
  EXPECT_EQ (merged.size (), all.size ()) << "the same hull vertices, however the views were grouped";
  EXPECT_EQ (merged.views (), 5u);
}
