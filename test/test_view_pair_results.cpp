/*
 * pcl_tensor: the results file of pair registrations (pcl_tensor_pairs --pairs -> pcl_tensor_model).
 */
#include "test_utils.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/io/tensor_view_cache_key.h>
#include <pcl/io/view_pair_results.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

namespace
{
  using pcl::registration::TensorRegistrationReport;
  using pcl::registration::TensorVerificationStage;

  /** A transform whose floats need all their digits: a random rotation and translation, not round numbers. */
  Eigen::Matrix4f
  awkwardTransform (unsigned seed)
  {
    std::mt19937 rng (seed);
    return pcl_tensor_test::randomRigidTransform (rng, 1234.5).matrix ().cast<float> ();
  }

  bool
  sameBits (const Eigen::Matrix4f& a, const Eigen::Matrix4f& b)
  {
    return std::memcmp (a.data (), b.data (), sizeof (float) * 16) == 0;
  }

  TensorRegistrationReport
  registeredReport ()
  {
    TensorRegistrationReport r;
    r.registered = true;
    r.transform = awkwardTransform (1);
    r.verification.transform = r.transform;
    r.verification.stage = TensorVerificationStage::PASSED;
    r.verification.icp_fitness = 0.00012345678901234;
    r.verification.fine_correspondences = 1234.0 / 7.0;
    r.hypotheses_tried = 3;
    r.hypotheses_skipped = 1;
    r.hypotheses_refused = 2;
    r.ambiguity_checks = 2;
    r.matches = 77;
    r.comparisons = 123456;
    r.model_tensors = 400;
    r.scene_tensors = 390;
    r.resolution = 0.0017;
    r.dimensions.D = Eigen::Vector3d (0.2, 0.15, 0.1);
    r.winning_match.model = 12;
    r.winning_match.scene = 34;
    r.winning_match.correlation = 0.61f;
    r.winning_match.overlap_ratio = 0.72f;
    r.winning_match.n_q = 56;
    r.failures[static_cast<std::size_t> (TensorVerificationStage::COARSE_OVERLAP)] = 1;
    r.failures[static_cast<std::size_t> (TensorVerificationStage::FINE_OVERLAP)] = 1;
    r.timings.total_ms = 12.5;
    return r;
  }

  TensorRegistrationReport
  notRegisteredReport ()
  {
    TensorRegistrationReport r;
    r.hypotheses_tried = 300;
    r.failures[static_cast<std::size_t> (TensorVerificationStage::COARSE_DIMENSIONS)] = 299;
    r.failures[static_cast<std::size_t> (TensorVerificationStage::FREE_SPACE)] = 1;
    return r;
  }

  TensorRegistrationReport
  ambiguousReport ()
  {
    TensorRegistrationReport r;
    r.ambiguous = true;
    r.hypotheses_tried = 5;
    r.verification.transform = awkwardTransform (2);
    r.rival_transform = awkwardTransform (3);
    return r;
  }

  std::vector<pcl::io::ViewPairResult>
  threeResults ()
  {
    return {pcl::io::makeViewPairResult ("views/view_00.ply", "views/view_01.ply", registeredReport ()),
            pcl::io::makeViewPairResult ("views/view_00.ply", "other/view_06.ply", notRegisteredReport ()),
            pcl::io::makeViewPairResult ("a b/\"quoted\".pcd", "views/view_01.ply", ambiguousReport ())};
  }

  void
  expectSameReport (const TensorRegistrationReport& e, const TensorRegistrationReport& a)
  {
    EXPECT_EQ (e.registered, a.registered);
    EXPECT_EQ (e.ambiguous, a.ambiguous);
    EXPECT_TRUE (sameBits (e.transform, a.transform)) << e.transform << "\nread back as\n" << a.transform;
    EXPECT_TRUE (sameBits (e.rival_transform, a.rival_transform));
    EXPECT_EQ (e.hypotheses_tried, a.hypotheses_tried);
    EXPECT_EQ (e.hypotheses_skipped, a.hypotheses_skipped);
    EXPECT_EQ (e.hypotheses_refused, a.hypotheses_refused);
    EXPECT_EQ (e.ambiguity_checks, a.ambiguity_checks);
    EXPECT_EQ (e.matches, a.matches);
    EXPECT_EQ (e.comparisons, a.comparisons);
    EXPECT_EQ (e.model_tensors, a.model_tensors);
    EXPECT_EQ (e.scene_tensors, a.scene_tensors);
    EXPECT_EQ (e.resolution, a.resolution);
    EXPECT_EQ (e.dimensions.D, a.dimensions.D);
    EXPECT_EQ (e.failures, a.failures);
    EXPECT_EQ (e.timings.total_ms, a.timings.total_ms);
    EXPECT_EQ (e.verification.passed (), a.verification.passed ());
    if (e.registered || e.ambiguous)
    {
      EXPECT_TRUE (sameBits (e.verification.transform, a.verification.transform));
    }
    if (e.registered)
    {
      EXPECT_EQ (e.verification.icp_fitness, a.verification.icp_fitness);
      EXPECT_EQ (e.verification.fine_correspondences, a.verification.fine_correspondences);
      EXPECT_EQ (e.winning_match.model, a.winning_match.model);
      EXPECT_EQ (e.winning_match.scene, a.winning_match.scene);
      EXPECT_EQ (e.winning_match.correlation, a.winning_match.correlation);
      EXPECT_EQ (e.winning_match.overlap_ratio, a.winning_match.overlap_ratio);
      EXPECT_EQ (e.winning_match.n_q, a.winning_match.n_q);
    }
  }

  std::string
  loadErrorOf (const std::string& path)
  {
    try
    {
      pcl::io::loadViewPairResults (path);
    }
    catch (const pcl::IOException& e)
    {
      return pcl::errorDescription (e);
    }
    return "";
  }
}

TEST (ViewPairResults, RoundTripOfRegisteredRefusedAndAmbiguousPairs)
{
  const auto written = threeResults ();
  const std::string path = ::testing::TempDir () + "pair_results.jsonl";
  pcl::io::saveViewPairResults (path, written);
  const auto read = pcl::io::loadViewPairResults (path);
  ASSERT_EQ (read.size (), written.size ());
  for (std::size_t i = 0; i < read.size (); ++i)
  {
    SCOPED_TRACE (i);
    EXPECT_EQ (read[i].model, written[i].model);
    EXPECT_EQ (read[i].scene, written[i].scene);
    EXPECT_EQ (read[i].model_file, written[i].model_file);
    EXPECT_EQ (read[i].scene_file, written[i].scene_file);
    expectSameReport (written[i].report, read[i].report);
  }
  // The keys are the views' ids, the same whatever path named the file.
  EXPECT_EQ (read[0].model, pcl::io::viewIdOf ("views/./view_00.ply"));
}

TEST (ViewPairResults, OneObjectPerLine)
{
  const std::string text = pcl::io::formatViewPairResults (threeResults ());
  std::size_t lines = 0;
  for (const char c : text)
    lines += c == '\n';
  EXPECT_EQ (lines, 3u);
  EXPECT_EQ (text.back (), '\n');
}

TEST (ViewPairResults, AnEmptyFileHoldsNoResult)
{
  EXPECT_TRUE (pcl::io::loadViewPairResults (pcl_tensor_test::writeTempFile ("no_results.jsonl", "")).empty ());
  EXPECT_TRUE (pcl::io::loadViewPairResults (pcl_tensor_test::writeTempFile ("blank_results.jsonl", "\n  \n")).empty ());
  pcl::io::saveViewPairResults (::testing::TempDir () + "saved_none.jsonl", {});
  EXPECT_TRUE (pcl::io::loadViewPairResults (::testing::TempDir () + "saved_none.jsonl").empty ());
}

TEST (ViewPairResults, GarbledLinesAreRefusedWithFileAndLine)
{
  const std::string good = pcl::io::formatViewPairResults ({threeResults ().front ()});
  std::string no_transform = good;
  no_transform.replace (no_transform.find ("\"transform\""), 11, "\"transfxrm\"");
  std::string bad_id = good;
  bad_id.replace (bad_id.find ("\"model_id\":\"") + 12, 1, "/");
  struct Case
  {
    const char* name;
    std::string text;
    const char* where;
  };
  const Case cases[] = {
    {"garbage.jsonl", good + "this is not JSON\n", "garbage.jsonl:2:"},
    {"cut.jsonl", good.substr (0, good.size () / 2) + "\n", "cut.jsonl:1:"},
    {"array.jsonl", "[1, 2]\n", "array.jsonl:1:"},
    {"no_transform.jsonl", "\n" + no_transform, "no_transform.jsonl:2:"},
    {"bad_id.jsonl", bad_id, "bad_id.jsonl:1:"},
  };
  for (const auto& c : cases)
  {
    const std::string message = loadErrorOf (pcl_tensor_test::writeTempFile (c.name, c.text));
    EXPECT_NE (message.find (c.where), std::string::npos) << c.name << ": " << message;
  }
  EXPECT_NE (loadErrorOf ("/nonexistent/results.jsonl").find ("/nonexistent/results.jsonl"), std::string::npos);
}

TEST (ViewPairResults, SavingReplacesTheFileWhole)
{
  const std::string path = ::testing::TempDir () + "replaced.jsonl";
  pcl::io::saveViewPairResults (path, threeResults ());
  pcl::io::saveViewPairResults (path, {threeResults ().back ()});
  ASSERT_EQ (pcl::io::loadViewPairResults (path).size (), 1u);
  EXPECT_THROW (pcl::io::saveViewPairResults ("/nonexistent/folder/r.jsonl", threeResults ()), pcl::IOException);
}

TEST (ViewPairResults, ACappedSearchRefusesWhatItWouldNotHaveReached)
{
  TensorRegistrationReport late = registeredReport ();
  late.hypotheses_tried = 25;
  const TensorRegistrationReport capped = pcl::io::reportWithinHypotheses (late, 20);
  EXPECT_FALSE (capped.registered);
  EXPECT_EQ (capped.hypotheses_tried, 20u);
  EXPECT_TRUE (capped.transform.isIdentity ());
  // Reached within the cap, or no cap: the report as it is.
  EXPECT_TRUE (pcl::io::reportWithinHypotheses (late, 25).registered);
  EXPECT_TRUE (pcl::io::reportWithinHypotheses (late, 0).registered);
  EXPECT_TRUE (pcl::io::reportWithinHypotheses (ambiguousReport (), 20).ambiguous);
}
