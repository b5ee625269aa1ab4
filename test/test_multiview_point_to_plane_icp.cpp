#include "test_utils.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/registration/multiview_point_to_plane_icp.h>
#include <pcl/registration/registration_error.h>
#include <pcl/simulation/example_object.h>
#include <pcl/simulation/synthetic_views.h>
#include <pcl/simulation/view_set.h>
#include <pcl/surface/scan_preparation.h>

#include <algorithm>

namespace
{
  using namespace pcl::registration;

  /** Fine meshes of a ring of 12 views, 30 degrees apart, of the example object, with their exact
    * poses relative to view 0. */
  struct Ring
  {
    std::vector<pcl::PreparedScan> scans;
    ViewPoses truth;
    double resolution = 0.0;
  };

  const Ring&
  ring ()
  {
    static const Ring r = [] {
      pcl::SyntheticViewParams params;
      params.camera.width = params.camera.height = 200;
      const auto views = pcl::renderSyntheticViews (pcl::makeExampleObject (), pcl::makeRingViewDirections (12, 30.0), params);
      Ring out;
      for (const auto& v : views)
      {
        out.scans.push_back (pcl::prepareScan (*v.view.cloud, v.view.viewpoint));
        out.truth.push_back (views[0].view.pose.inverse () * v.view.pose);
        out.resolution += out.scans.back ().resolution / static_cast<double> (views.size ());
      }
      return out;
    } ();
    return r;
  }

  std::vector<const pcl::ScanMesh*>
  meshes (const Ring& r)
  {
    std::vector<const pcl::ScanMesh*> m;
    for (const auto& s : r.scans)
      m.push_back (&s.fine);
    return m;
  }

  ViewPairs
  ringPairs (int n)
  {
    ViewPairs pairs;
    for (int i = 0; i + 1 < n; ++i)
      pairs.emplace_back (i, i + 1);
    pairs.emplace_back (0, n - 1);
    return pairs;
  }

  /** A small rigid motion: \a degrees about a random axis and \a distance along a random direction. */
  Eigen::Affine3d
  perturbation (std::mt19937& rng, double degrees, double distance)
  {
    std::normal_distribution<double> g;
    const Eigen::Vector3d axis = Eigen::Vector3d (g (rng), g (rng), g (rng)).normalized ();
    const Eigen::Vector3d dir = Eigen::Vector3d (g (rng), g (rng), g (rng)).normalized ();
    Eigen::Affine3d t = Eigen::Affine3d::Identity ();
    t.linear () = Eigen::AngleAxisd (degrees * M_PI / 180.0, axis).toRotationMatrix ();
    t.translation () = distance * dir;
    return t;
  }

  /** The true poses with every view but the first moved by perturbation (rng, 0.3 deg, 1 d_res): about
    * view 0's sensor (0.3 m away) that is 1-3 d_res at the object, within the pairing distance. */
  ViewPoses
  perturbedTruth (const Ring& r, std::uint32_t seed)
  {
    std::mt19937 rng (seed);  // fixed seed: the same motions every run
    ViewPoses poses = r.truth;
    for (std::size_t i = 1; i < poses.size (); ++i)
      poses[i] = perturbation (rng, 0.3, r.resolution) * r.truth[i];
    return poses;
  }

  /** How far the view's centroid lands from where the truth puts it, in d_res. */
  double
  centroidError (const pcl::ScanMesh& mesh, const Eigen::Affine3d& a, const Eigen::Affine3d& b, double resolution)
  {
    Eigen::Vector3d c = Eigen::Vector3d::Zero ();
    for (const auto& p : *mesh.cloud)
      c += p.getVector3fMap ().cast<double> ();
    c /= static_cast<double> (mesh.cloud->size ());
    return (a * c - b * c).norm () / resolution;
  }
}

TEST (MultiviewPointToPlaneIcp, RecoversPerturbedRingPoses)
{
  const Ring& r = ring ();
  const ViewPoses initial = perturbedTruth (r, 2006);

  int calls = 0;
  const MultiviewIcpResult result = multiviewPointToPlaneIcp (meshes (r), initial, ringPairs (12), 0, r.resolution, {},
                                                              [&] (int, int) { ++calls; });
  EXPECT_EQ (calls, result.iterations);
  EXPECT_LT (result.rms_after, result.rms_before);
  EXPECT_TRUE (result.poses[0].isApprox (r.truth[0])) << "the fixed view moved";
  for (std::size_t i = 1; i < r.truth.size (); ++i)
  {
    const double rotation = pcl::rotationErrorDeg (result.poses[i].rotation (), r.truth[i].rotation ());
    const double centroid = centroidError (r.scans[i].fine, result.poses[i], r.truth[i], r.resolution);
    EXPECT_LT (rotation, 0.02) << "view " << i << " (started 0.3 deg off)";
    EXPECT_LT (centroid, 0.05) << "view " << i << " (started 1-3 d_res off)";
  }
}

TEST (MultiviewPointToPlaneIcp, ViewsInNoPairKeepTheirPose)
{
  const Ring& r = ring ();
  const ViewPoses initial = perturbedTruth (r, 7);
  const MultiviewIcpResult result = multiviewPointToPlaneIcp (meshes (r), initial, {{0, 1}, {1, 2}}, 0, r.resolution, {});
  for (std::size_t i = 3; i < r.truth.size (); ++i)
    EXPECT_TRUE (result.poses[i].isApprox (initial[i])) << "view " << i << " is in no pair but moved";
  EXPECT_LT (pcl::rotationErrorDeg (result.poses[2].rotation (), r.truth[2].rotation ()), 0.02);
}

TEST (MultiviewPointToPlaneIcp, FindsTheNeighboursOnTheRing)
{
  const Ring& r = ring ();
  const ViewPairs pairs = findOverlappingViews (meshes (r), r.truth, {}, r.resolution, 2.0, 0.3);
  for (const auto& p : ringPairs (12))
    EXPECT_EQ (std::count (pairs.begin (), pairs.end (), std::make_pair (std::min (p.first, p.second), std::max (p.first, p.second))), 1)
        << "views " << p.first << " and " << p.second << " are 30 degrees apart";
  EXPECT_EQ (std::count (pairs.begin (), pairs.end (), std::make_pair (0, 6)), 0) << "front and back do not overlap";
  std::vector<bool> use (12, true);
  use[1] = false;
  for (const auto& p : findOverlappingViews (meshes (r), r.truth, use, r.resolution, 2.0, 0.3))
    EXPECT_TRUE (p.first != 1 && p.second != 1);
}

// A model extended with new views: the views settled before stay where they are, to the bit, and only
// the new ones move onto them.
TEST (MultiviewPointToPlaneIcp, SeveralFixedViewsKeepTheirPosesExactly)
{
  const Ring& r = ring ();
  ViewPoses initial = perturbedTruth (r, 11);
  std::vector<bool> fixed (12, false);
  for (int i = 0; i < 9; ++i)
  {
    fixed[i] = true;
    initial[i] = r.truth[i];
  }
  const MultiviewIcpResult result = multiviewPointToPlaneIcp (meshes (r), initial, ringPairs (12), fixed, r.resolution, {});
  for (int i = 0; i < 9; ++i)
    EXPECT_TRUE (result.poses[i].matrix () == initial[i].matrix ()) << "fixed view " << i << " moved";
  for (int i = 9; i < 12; ++i)
  {
    EXPECT_LT (pcl::rotationErrorDeg (result.poses[i].rotation (), r.truth[i].rotation ()), 0.02) << "view " << i;
    EXPECT_LT (centroidError (r.scans[i].fine, result.poses[i], r.truth[i], r.resolution), 0.05) << "view " << i;
  }
  EXPECT_THROW (multiviewPointToPlaneIcp (meshes (r), initial, ringPairs (12), std::vector<bool> (12, false), r.resolution, {}),
                pcl::BadArgumentException) << "no view fixed: the frame is not defined";
  EXPECT_THROW (multiviewPointToPlaneIcp (meshes (r), initial, ringPairs (12), std::vector<bool> (3, true), r.resolution, {}),
                pcl::BadArgumentException);
}

// Only the candidates given are tried, and of them those that overlap are returned, as
// findOverlappingViews() finds them among all pairs.
TEST (MultiviewPointToPlaneIcp, SelectsTheOverlappingCandidates)
{
  const Ring& r = ring ();
  const ViewPairs all = findOverlappingViews (meshes (r), r.truth, {}, r.resolution, 2.0, 0.3);
  const ViewPairs candidates{{11, 0}, {11, 5}, {11, 10}, {3, 4}};
  const ViewPairs selected = selectOverlappingPairs (meshes (r), r.truth, candidates, r.resolution, 2.0, 0.3);
  const ViewPairs expected{{11, 0}, {11, 10}, {3, 4}};
  EXPECT_EQ (selected, expected) << "11 and 5 are 180 degrees apart; the others neighbours";
  for (const auto& p : selected)
    EXPECT_EQ (std::count (all.begin (), all.end (), std::make_pair (std::min (p.first, p.second), std::max (p.first, p.second))), 1);
  EXPECT_THROW (selectOverlappingPairs (meshes (r), r.truth, {{0, 0}}, r.resolution, 2.0, 0.3), pcl::BadArgumentException);
}

TEST (MultiviewPointToPlaneIcp, RefusesBadInput)
{
  const Ring& r = ring ();
  EXPECT_THROW (multiviewPointToPlaneIcp (meshes (r), ViewPoses (3), {}, 0, r.resolution, {}), pcl::BadArgumentException);
  EXPECT_THROW (multiviewPointToPlaneIcp (meshes (r), r.truth, {{0, 12}}, 0, r.resolution, {}), pcl::BadArgumentException);
  EXPECT_THROW (multiviewPointToPlaneIcp (meshes (r), r.truth, {{0, 1}}, 12, r.resolution, {}), pcl::BadArgumentException);
  EXPECT_THROW (multiviewPointToPlaneIcp (meshes (r), r.truth, {{0, 1}}, 0, 0.0, {}), pcl::BadArgumentException);
}

TEST (MeshBoundaryVertices, OnlyTheRimOfAGrid)
{
  // A 3 x 3 grid of vertices, 8 triangles: only the centre vertex is inside.
  pcl::ScanMesh mesh;
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x)
    {
      pcl::PointNormal p;
      p.x = static_cast<float> (x);
      p.y = static_cast<float> (y);
      p.z = 0.0f;
      mesh.cloud->push_back (p);
    }
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x)
    {
      const int i = y * 3 + x;
      pcl::Vertices a, b;
      a.vertices = {i, i + 1, i + 4};
      b.vertices = {i, i + 4, i + 3};
      mesh.polygons.push_back (a);
      mesh.polygons.push_back (b);
    }
  const std::vector<bool> boundary = pcl::meshBoundaryVertices (mesh);
  ASSERT_EQ (boundary.size (), 9u);
  for (int i = 0; i < 9; ++i)
    EXPECT_EQ (boundary[i], i != 4) << "vertex " << i;
}
