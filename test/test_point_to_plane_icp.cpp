/*
 * pcl_tensor: known-answer tests of the verification's point-to-plane ICP, one stage and coarse to fine.
 */
#include "test_utils.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/registration/point_to_plane_icp.h>
#include <pcl/registration/registration_error.h>

namespace
{
  /** z = 5 mm sin(60 x) cos(45 y) on a 100 x 100 grid of 1 mm pitch, with its exact normals. */
  pcl::PointCloud<pcl::PointNormal>
  wavySurface ()
  {
    pcl::PointCloud<pcl::PointNormal> cloud;
    for (int i = 0; i < 100; ++i)
      for (int j = 0; j < 100; ++j)
      {
        const double x = 1e-3 * (i - 50), y = 1e-3 * (j - 50);
        const double z = 5e-3 * std::sin (60 * x) * std::cos (45 * y);
        const double zx = 0.3 * std::cos (60 * x) * std::cos (45 * y), zy = -0.225 * std::sin (60 * x) * std::sin (45 * y);
        pcl::PointNormal p;
        p.getVector3fMap () = Eigen::Vector3f (x, y, z);
        p.getNormalVector3fMap () = Eigen::Vector3d (-zx, -zy, 1.0).normalized ().cast<float> ();
        cloud.push_back (p);
      }
    return cloud;
  }

  /** A known motion of 2 degrees and 4 mm. */
  Eigen::Affine3d
  knownMotion ()
  {
    return Eigen::Translation3d (3e-3, -2e-3, 1.5e-3) * Eigen::AngleAxisd (2.0 * M_PI / 180.0, Eigen::Vector3d (1, 2, 0.5).normalized ());
  }

  /** Every \a step-th point of \a target, moved by the inverse of \a truth: ICP must recover \a truth. */
  pcl::PointCloud<pcl::PointNormal>
  movedSample (const pcl::PointCloud<pcl::PointNormal>& target, const Eigen::Affine3d& truth, std::size_t step)
  {
    pcl::PointCloud<pcl::PointNormal> source;
    for (std::size_t k = 0; k < target.size (); k += step)
    {
      pcl::PointNormal p = target[k];
      p.getVector3fMap () = (truth.inverse () * p.getVector3fMap ().cast<double> ()).cast<float> ();
      source.push_back (p);
    }
    return source;
  }

  /** ICP from 8 mm down to 1 mm, in four stages. */
  pcl::registration::PointToPlaneIcpParams
  stagedParams ()
  {
    pcl::registration::PointToPlaneIcpParams params;
    params.max_iterations = 30;
    params.max_distance = 8e-3;
    params.final_distance = 1e-3;
    return params;
  }

  /** The wavy surface as target, with its search, and every \a step-th point of it moved by the
    * inverse of knownMotion() as source. */
  struct KnownMotionCase
  {
    explicit KnownMotionCase (std::size_t step)
      : target (wavySurface ()), truth (knownMotion ()), source (movedSample (target, truth, step))
    {
      search.setInputCloud (target);
    }
    pcl::PointCloud<pcl::PointNormal> target;
    Eigen::Affine3d truth;
    pcl::PointCloud<pcl::PointNormal> source;
    pcl::BoundedNearestSearch search{2e-3f};
  };

  void
  expectTruthRecovered (const Eigen::Matrix4f& estimate, const Eigen::Affine3d& truth)
  {
    const auto e = pcl::registrationError (Eigen::Affine3d (estimate.cast<double> ()), truth, 1e-3);
    EXPECT_LT (e.rotation_deg, 0.01);
    EXPECT_LT (e.translation_resolutions, 0.01);
  }
}

TEST (PointToPlaneIcp, CoarseToFineRecoversAMotionBeyondItsFinalDistance)
{
  const KnownMotionCase c (7);
  auto params = stagedParams ();
  const auto staged = pcl::registration::pointToPlaneIcp (c.source, c.target, c.search, Eigen::Matrix4f::Identity (), params);
  expectTruthRecovered (staged.transform, c.truth);
  EXPECT_LT (staged.rms, 1e-5);
  EXPECT_GT (staged.iterations, 0);
  // Four stages (8, 4, 2, 1 mm), so more iterations than the first stage alone.
  params.final_distance = 0.0;
  const auto single = pcl::registration::pointToPlaneIcp (c.source, c.target, c.search, Eigen::Matrix4f::Identity (), params);
  EXPECT_GE (staged.iterations, single.iterations + 3);
}

TEST (PointToPlaneIcp, BadParametersAreRefused)
{
  const auto target = wavySurface ();
  pcl::BoundedNearestSearch search (2e-3f);
  search.setInputCloud (target);
  pcl::registration::PointToPlaneIcpParams params;
  params.max_distance = 0.0;
  EXPECT_THROW (pcl::registration::pointToPlaneIcp (target, target, search, Eigen::Matrix4f::Identity (), params), pcl::BadArgumentException);
  params.max_distance = 1e-3;
  params.final_distance = -1.0;
  EXPECT_THROW (pcl::registration::pointToPlaneIcp (target, target, search, Eigen::Matrix4f::Identity (), params), pcl::BadArgumentException);
  params.final_distance = 0.0;
  params.coarse_stage_tolerance = 0.5;
  EXPECT_THROW (pcl::registration::pointToPlaneIcp (target, target, search, Eigen::Matrix4f::Identity (), params), pcl::BadArgumentException);
  params.coarse_stage_tolerance = 1.0;
  params.coarse_stage_step = 0;
  EXPECT_THROW (pcl::registration::pointToPlaneIcp (target, target, search, Eigen::Matrix4f::Identity (), params), pcl::BadArgumentException);
  params.coarse_stage_step = 1;
  params.max_normal_angle = 3.2;
  EXPECT_THROW (pcl::registration::pointToPlaneIcp (target, target, search, Eigen::Matrix4f::Identity (), params), pcl::BadArgumentException);
  params.max_normal_angle = -0.1;
  EXPECT_THROW (pcl::registration::pointToPlaneIcp (target, target, search, Eigen::Matrix4f::Identity (), params), pcl::BadArgumentException);
}

TEST (PointToPlaneIcp, PairsWhoseNormalsDisagreeAreNotUsed)
{
  const auto target = wavySurface ();
  pcl::BoundedNearestSearch search (2e-3f);
  search.setInputCloud (target);
  // The source is the target itself, every third point's normal turned by 90 degrees about x.
  auto source = target;
  std::size_t turned = 0;
  for (std::size_t k = 0; k < source.size (); k += 3, ++turned)
    source[k].getNormalVector3fMap () = Eigen::AngleAxisf (0.5f * static_cast<float> (M_PI), Eigen::Vector3f::UnitX ()) *
                                        source[k].getNormalVector3fMap ();
  pcl::registration::PointToPlaneIcpParams params;
  params.max_distance = 1e-3;
  const auto all = pcl::registration::pointToPlaneIcp (source, target, search, Eigen::Matrix4f::Identity (), params);
  EXPECT_EQ (all.pairs, source.size ());
  params.max_normal_angle = 60.0 * M_PI / 180.0;
  const auto compatible = pcl::registration::pointToPlaneIcp (source, target, search, Eigen::Matrix4f::Identity (), params);
  EXPECT_EQ (compatible.pairs, source.size () - turned);
  expectTruthRecovered (compatible.transform, Eigen::Affine3d::Identity ());
}

// A plate 3 mm thick, its two faces the wavy surface with opposite normals, and a sample of the top
// face 1.2 mm below it: the near-bottom points pair with the bottom face, whose planes pull the pose
// off (4.6 degrees and 5.8 mm). Compatible normals pair the top face only, and recover the truth.
TEST (PointToPlaneIcp, CompatibleNormalsKeepAThinPlatesFacesApart)
{
  const auto top = wavySurface ();
  auto plate = top;
  for (auto p : top)
  {
    p.z -= 3e-3f;
    p.getNormalVector3fMap () = -p.getNormalVector3fMap ();
    plate.push_back (p);
  }
  pcl::BoundedNearestSearch search (2e-3f);
  search.setInputCloud (plate);
  const Eigen::Affine3d truth = Eigen::Translation3d (0.0, 0.0, 1.2e-3) * Eigen::AngleAxisd (2.0 * M_PI / 180.0, Eigen::Vector3d::UnitX ());
  const auto source = movedSample (top, truth, 5);
  auto params = stagedParams ();
  const auto all = pcl::registration::pointToPlaneIcp (source, plate, search, Eigen::Matrix4f::Identity (), params);
  const auto e = pcl::registrationError (Eigen::Affine3d (all.transform.cast<double> ()), truth, 1e-3);
  std::cout << "every pair: " << e.rotation_deg << " deg, " << e.translation_resolutions << " mm off" << std::endl;
  EXPECT_GT (e.rotation_deg, 1.0) << "the case this test guards has changed";
  params.max_normal_angle = 60.0 * M_PI / 180.0;
  const auto compatible = pcl::registration::pointToPlaneIcp (source, plate, search, Eigen::Matrix4f::Identity (), params);
  expectTruthRecovered (compatible.transform, truth);
}

TEST (PointToPlaneIcp, LooseCoarseStagesReachTheSamePoseInFewerIterations)
{
  const KnownMotionCase c (3);
  auto params = stagedParams ();
  params.min_translation = 1e-7;
  params.coarse_stage_tolerance = 1.0;
  const auto strict = pcl::registration::pointToPlaneIcp (c.source, c.target, c.search, Eigen::Matrix4f::Identity (), params);
  params.coarse_stage_tolerance = 1000.0;
  const auto loose = pcl::registration::pointToPlaneIcp (c.source, c.target, c.search, Eigen::Matrix4f::Identity (), params);
  // The last stage still converges fully, so the pose is the one the strict schedule reaches.
  expectTruthRecovered (loose.transform, c.truth);
  EXPECT_LT (loose.iterations, strict.iterations);
}

// min_pairs: a stage that ends with fewer pairs stops the refinement; one that has them goes on.
TEST (PointToPlaneIcp, TooFewPairsAtACoarseStageStopTheRefinement)
{
  const KnownMotionCase c (7);
  auto params = stagedParams ();
  // Every source point pairs at 8 mm: a bar at the sample's size is met, and the result is unchanged.
  params.min_pairs = c.source.size ();
  const auto met = pcl::registration::pointToPlaneIcp (c.source, c.target, c.search, Eigen::Matrix4f::Identity (), params);
  EXPECT_FALSE (met.stopped_early);
  expectTruthRecovered (met.transform, c.truth);
  // One pair more than the sample holds cannot be met: only the first stage runs.
  params.min_pairs = c.source.size () + 1;
  const auto stopped = pcl::registration::pointToPlaneIcp (c.source, c.target, c.search, Eigen::Matrix4f::Identity (), params);
  EXPECT_TRUE (stopped.stopped_early);
  params.min_pairs = 0;
  params.final_distance = 0.0;
  const auto first_stage = pcl::registration::pointToPlaneIcp (c.source, c.target, c.search, Eigen::Matrix4f::Identity (), params);
  EXPECT_EQ (stopped.iterations, first_stage.iterations);
  EXPECT_LT (stopped.iterations, met.iterations);
}

// coarse_stage_step: a coarse stage pairs a subsample and counts its pairs for the whole source; the
// last stage pairs every point, so the pose is the one full stages reach.
TEST (PointToPlaneIcp, SubsampledCoarseStagesReachTheSamePose)
{
  const KnownMotionCase c (3);
  auto params = stagedParams ();
  params.coarse_stage_step = 2;  // strides 8, 4, 2, 1 at 8, 4, 2, 1 mm
  const auto subsampled = pcl::registration::pointToPlaneIcp (c.source, c.target, c.search, Eigen::Matrix4f::Identity (), params);
  expectTruthRecovered (subsampled.transform, c.truth);
  EXPECT_FALSE (subsampled.stopped_early);
  // Every point pairs in the last stage, which no subsample runs.
  EXPECT_EQ (subsampled.pairs, c.source.size ());
  // A source under 128 points is paired whole at every stage. Here every point but each 8th lies 30 mm
  // off the surface: a first stage at a stride of 8 would pair only the 13 on it and count them as all
  // 104, but paired whole, the source's 13 pairs are under a bar of half of it.
  KnownMotionCase small (97);  // 104 points spread over the surface
  for (std::size_t k = 0; k < small.source.size (); ++k)
    if (k % 8 != 0)
      small.source[k].z += 30e-3f;
  params.min_pairs = small.source.size () / 2;
  const auto whole = pcl::registration::pointToPlaneIcp (small.source, small.target, small.search, Eigen::Matrix4f::Identity (), params);
  EXPECT_TRUE (whole.stopped_early);
  EXPECT_EQ (whole.pairs, 13u);
}

TEST (PointToPlaneIcp, SubsampledCoarseStagePairsOnlyItsSample)
{
  // Every odd point lies 30 mm off the surface: no stage pairs it. The first of two stages (8, then
  // 4 mm) pairs every second point with a step of 2, i.e. only the even points, which all pair.
  KnownMotionCase c (3);
  for (std::size_t k = 1; k < c.source.size (); k += 2)
    c.source[k].z += 30e-3f;
  auto params = stagedParams ();
  params.final_distance = 4e-3;
  params.min_pairs = c.source.size () / 2 + 2;  // more than the even points, fewer than all
  const auto full = pcl::registration::pointToPlaneIcp (c.source, c.target, c.search, Eigen::Matrix4f::Identity (), params);
  EXPECT_TRUE (full.stopped_early);
  params.coarse_stage_step = 2;
  const auto subsampled = pcl::registration::pointToPlaneIcp (c.source, c.target, c.search, Eigen::Matrix4f::Identity (), params);
  EXPECT_FALSE (subsampled.stopped_early);
  expectTruthRecovered (subsampled.transform, c.truth);
  EXPECT_EQ (subsampled.pairs, (c.source.size () + 1) / 2);  // the last stage pairs every point: the even ones
}

// continue_after_stage: told each stage's pose before the last, it can end the refinement; a check that
// always goes on leaves the result as it is without one.
TEST (PointToPlaneIcp, StageCheckSeesEachStageAndCanEndTheRefinement)
{
  const KnownMotionCase c (7);
  auto params = stagedParams ();  // stages at 8, 4, 2 and 1 mm
  const auto plain = pcl::registration::pointToPlaneIcp (c.source, c.target, c.search, Eigen::Matrix4f::Identity (), params);
  ASSERT_EQ (plain.stage_transforms.size (), 4u);
  EXPECT_EQ (plain.stage_transforms.back (), plain.transform);
  EXPECT_FALSE (plain.abandoned);

  std::vector<std::size_t> seen;
  params.continue_after_stage = [&seen] (std::size_t stage, const Eigen::Matrix4f&) { seen.push_back (stage); return true; };
  const auto checked = pcl::registration::pointToPlaneIcp (c.source, c.target, c.search, Eigen::Matrix4f::Identity (), params);
  EXPECT_EQ (seen, (std::vector<std::size_t>{0, 1, 2})) << "called after every stage but the last";
  EXPECT_EQ (checked.transform, plain.transform);
  EXPECT_EQ (checked.iterations, plain.iterations);
  EXPECT_FALSE (checked.abandoned);

  // Ending after the second stage: its pose is the result, and the later stages do not run.
  params.continue_after_stage = [] (std::size_t stage, const Eigen::Matrix4f&) { return stage < 1; };
  const auto ended = pcl::registration::pointToPlaneIcp (c.source, c.target, c.search, Eigen::Matrix4f::Identity (), params);
  EXPECT_TRUE (ended.abandoned);
  EXPECT_FALSE (ended.stopped_early);
  ASSERT_EQ (ended.stage_transforms.size (), 2u);
  EXPECT_EQ (ended.stage_transforms[1], plain.stage_transforms[1]);
  EXPECT_EQ (ended.transform, plain.stage_transforms[1]);
  EXPECT_LT (ended.iterations, plain.iterations);
}
