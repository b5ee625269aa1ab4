/*
 * eval_multiview: multiview registration of ordered views (issue 6; paper Sections 4.2, 5 and 6).
 *
 *   eval_multiview [--dragon] [--bunny] [--lum] [--out DIR] [options]   (see --help)
 *
 * Registers every scan of a Stanford set in .conf order with MultiviewTensorRegistration, scores the
 * poses against the .conf after the pairwise stage and after the global step (and after PCL's LUM on
 * the same pairs with --lum), prints the time of each stage and writes one CSV per set.
 */
#include "eval/eval_views.h"
#include "eval/multiview_evaluation.h"

#include <pcl/common/time.h>
#include <pcl/console/parse.h>
#include <pcl/console/print.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace pcl_tensor_eval;

namespace
{
  struct Options
  {
    std::string data = PCL_TENSOR_SHARED_DATA;
    std::string out = "bench_results";
    pcl::registration::MultiviewRegistrationParams params;
    bool lum = false;
    int lum_rounds = 10;
  };

  void
  printHelp (const char* name)
  {
    const Options d;
    std::printf ("Multiview registration measurements of issue 6 (Mian et al., IJCV 2006, Sections 4.2, 5, 6).\n\n"
                 "Usage: %s [--dragon] [--bunny] [options]\n\n"
                 "  --dragon             the 15 dragon_stand scans in turntable order with loop closure -> multiview_dragon.csv\n"
                 "  --bunny              the 10 bunny scans of bun.conf, each tried against all registered views -> multiview_bunny.csv\n"
                 "  --lum                also run PCL's LUM as the global step on the same pairs, for comparison\n"
                 "  --lum-rounds N       correspondence rounds of LUM (default %d)\n"
                 "  --keep-best          try every registered view and keep the best verified registration\n"
                 "  --max-references N   registered views tried per view, 0 = all (default %d)\n"
                 "  --global-iterations N  iterations of the global step (default %d)\n"
                 "  --global-distance D  pairing distance of the global step in d_res (default %g)\n"
                 "  --global-tolerance T  global verification: allowed excess over D in d_res (default %g)\n"
                 "  --fine-dimension-tolerance T  local verification after ICP: allowed excess over D in d_res (default %g)\n"
                 "  --checked-dimensions N  largest principal extents both dimension checks compare with D (default %d)\n"
                 "  --min-overlap F      pairs found for the global step: overlap fraction, 0 = none (default %g)\n"
                 "  --out DIR            where the CSVs go (default %s)\n"
                 "  --data DIR           third-party data (default %s)\n",
                 name, d.lum_rounds, d.params.max_references, d.params.global.max_iterations, d.params.global.max_distance,
                 d.params.global_verification.tolerance, d.params.pairwise.verification.fine_dimension_tolerance,
                 d.params.pairwise.verification.checked_dimensions, d.params.min_overlap, d.out.c_str (), d.data.c_str ());
  }

  void
  printProgress (pcl::registration::MultiviewStage stage, std::size_t done, std::size_t total)
  {
    if (done == total)
      std::printf ("  %s: %zu/%zu done\n", pcl::registration::toString (stage).c_str (), done, total);
  }

  void
  printSummary (const char* label, const PoseErrorSummary& s)
  {
    std::printf ("  %-10s %2zu views  rotation max %.3f deg, median %.3f deg   translation max %.2f d_res, median %.2f d_res\n", label,
                 s.views, s.max_rotation_deg, s.median_rotation_deg, s.max_translation_res, s.median_translation_res);
  }

  std::vector<bool>
  registeredFlags (const pcl::registration::MultiviewRegistrationResult& result)
  {
    std::vector<bool> r;
    for (const auto& v : result.views)
      r.push_back (v.registered);
    return r;
  }

  /** Registers one Stanford set and prints and writes its errors and timings. */
  void
  evaluateSet (const std::string& label, const std::string& conf, const pcl::registration::MultiviewRegistrationParams& params,
               const Options& options)
  {
    std::printf ("%s (%s)\n", label.c_str (), conf.c_str ());
    pcl::StopWatch watch;
    const EvalViews views = loadStanfordViews (conf);
    const double load_ms = watch.getTime ();

    pcl::registration::MultiviewTensorRegistration registration;
    registration.setParams (params);
    registration.setProgressCallback (printProgress);
    const auto result = registration.compute (multiviewInputs (views));

    const std::vector<bool> registered = registeredFlags (result);
    pcl::registration::ViewPoses pairwise, global;
    for (const auto& v : result.views)
    {
      pairwise.push_back (v.pairwise_pose);
      global.push_back (v.pose);
    }
    const auto pairwise_errors = poseErrors (views, pairwise, registered, result.reference, result.resolution);
    const auto global_errors = poseErrors (views, global, registered, result.reference, result.resolution);
    const auto best_frame_errors = poseErrorsInBestFrame (views, global, registered, result.resolution);
    std::vector<ViewPoseError> lum_errors (views.size ());
    double lum_ms = 0.0;
    if (options.lum && result.registeredCount () > 1)
    {
      watch.reset ();
      const auto lum = lumGlobalRegistration (result, options.lum_rounds, params.global.sample_points, params.global.max_distance);
      lum_ms = watch.getTime ();
      lum_errors = poseErrors (views, lum, registered, result.reference, result.resolution);
    }

    std::filesystem::create_directories (options.out);
    std::ofstream csv (options.out + "/multiview_" + label + ".csv");
    csv << "view,registered,reference,hypotheses,globally_refused,global_excess_res,pairwise_rot_deg,pairwise_trans_res,"
           "global_rot_deg,global_trans_res,best_frame_rot_deg,best_frame_trans_res,lum_rot_deg,lum_trans_res,prepare_ms,tensors_ms,pairwise_ms\n";
    for (std::size_t i = 0; i < views.size (); ++i)
    {
      const auto& v = result.views[i];
      const std::string reference = v.reference >= 0 ? result.views[v.reference].name : "";
      std::printf ("  %-22s %-3s ref %-22s hyp %3zu refused %zu excess %5.2f  pairwise %.3f deg %.2f res  global %.3f deg %.2f res  best frame %.3f deg %.2f res%s%s\n",
                   v.name.c_str (), v.registered ? "yes" : "NO", reference.c_str (), v.pairwise.hypotheses_tried, v.globally_refused,
                   v.global_excess, pairwise_errors[i].rotation_deg, pairwise_errors[i].translation_res, global_errors[i].rotation_deg,
                   global_errors[i].translation_res, best_frame_errors[i].rotation_deg, best_frame_errors[i].translation_res,
                   v.error.empty () ? "" : "  ", v.error.c_str ());
      if (!v.registered)
      {
        std::printf ("    last tried: %zu matches, failures per stage:", v.pairwise.matches);
        for (const std::size_t f : v.pairwise.failures)
          std::printf (" %zu", f);
        std::printf ("\n");
      }
      csv << v.name << ',' << v.registered << ',' << reference << ',' << v.pairwise.hypotheses_tried << ',' << v.globally_refused << ','
          << v.global_excess << ',' << pairwise_errors[i].rotation_deg << ',' << pairwise_errors[i].translation_res << ','
          << global_errors[i].rotation_deg << ',' << global_errors[i].translation_res << ',' << best_frame_errors[i].rotation_deg << ','
          << best_frame_errors[i].translation_res << ',' << lum_errors[i].rotation_deg << ','
          << lum_errors[i].translation_res << ',' << v.prepare_ms << ',' << v.tensors_ms << ',' << v.pairwise_ms << '\n';
    }
    {
      // How the union of the views, at their true poses and in order, compares with Eq. 1's D: what
      // global verification must allow.
      std::vector<Eigen::Vector3d> points;
      std::printf ("  D = [%.4f %.4f %.4f]; extents of the first k views at their true poses, minus D, in d_res:\n   ",
                   result.dimensions.D.x (), result.dimensions.D.y (), result.dimensions.D.z ());
      for (std::size_t i = 0; i < views.size (); ++i)
      {
        if (!result.views[i].prepared)
          continue;
        for (const auto& p : *result.views[i].prepared->fine.cloud)
          points.push_back (views[i].pose * p.getVector3fMap ().cast<double> ());
        const Eigen::Vector3d e = (pcl::principalExtents (points) - result.dimensions.D) / result.resolution;
        std::printf (" [%.0f %.0f %.0f]", e.x (), e.y (), e.z ());
      }
      std::printf ("\n");
    }
    if (result.reference >= 0 && !result.pairs.empty ())
    {
      // The same pairs' RMS point-to-plane distance at the true poses, for comparison with the global step's.
      std::vector<const pcl::ScanMesh*> meshes;
      pcl::registration::ViewPoses truth;
      for (std::size_t i = 0; i < views.size (); ++i)
      {
        meshes.push_back (result.views[i].prepared ? &result.views[i].prepared->fine : nullptr);
        truth.push_back (views[result.reference].pose.inverse () * views[i].pose);
      }
      auto one = params.global;
      one.max_iterations = 1;
      const auto at_truth = pcl::registration::multiviewPointToPlaneIcp (meshes, truth, result.pairs, result.reference,
                                                                         result.resolution, one);
      std::printf ("  the global step's pairs at the true poses: rms %.3f d_res\n", at_truth.rms_before / result.resolution);
    }
    std::printf ("  registered %zu/%zu, d_res %.6f, D = [%.4f %.4f %.4f], global step: %zu pairs, %d iterations, rms %.3f -> %.3f d_res\n",
                 result.registeredCount (), views.size (), result.resolution, result.dimensions.D.x (), result.dimensions.D.y (),
                 result.dimensions.D.z (), result.pairs.size (), result.global.iterations, result.global.rms_before / result.resolution,
                 result.global.rms_after / result.resolution);
    printSummary ("pairwise", summarize (pairwise_errors));
    printSummary ("global", summarize (global_errors));
    printSummary ("best frame", summarize (best_frame_errors));
    if (options.lum)
      printSummary ("LUM", summarize (lum_errors));
    const auto& t = result.timings;
    std::printf ("  time (ms): loading %.0f, meshing %.0f, tensors %.0f, pairwise %.0f, global %.0f; registration %.0f, with loading %.0f%s\n",
                 load_ms, t.prepare_ms, t.tensors_ms, t.pairwise_ms, t.global_ms, t.total_ms, load_ms + t.total_ms,
                 options.lum ? (", LUM " + std::to_string (static_cast<int> (lum_ms))).c_str () : "");
  }
}

int
main (int argc, char** argv)
{
  std::setvbuf (stdout, nullptr, _IOLBF, 0);
  if (argc < 2 || pcl::console::find_switch (argc, argv, "--help") || pcl::console::find_switch (argc, argv, "-h"))
  {
    printHelp (argv[0]);
    return argc < 2 ? 1 : 0;
  }
  Options options;
  pcl::console::parse_argument (argc, argv, "--data", options.data);
  pcl::console::parse_argument (argc, argv, "--out", options.out);
  options.lum = pcl::console::find_switch (argc, argv, "--lum");
  pcl::console::parse_argument (argc, argv, "--lum-rounds", options.lum_rounds);
  auto& p = options.params;
  p.keep_best = pcl::console::find_switch (argc, argv, "--keep-best");
  pcl::console::parse_argument (argc, argv, "--max-references", p.max_references);
  pcl::console::parse_argument (argc, argv, "--global-iterations", p.global.max_iterations);
  pcl::console::parse_argument (argc, argv, "--global-distance", p.global.max_distance);
  pcl::console::parse_argument (argc, argv, "--min-overlap", p.min_overlap);
  pcl::console::parse_argument (argc, argv, "--global-tolerance", p.global_verification.tolerance);
  pcl::console::parse_argument (argc, argv, "--fine-dimension-tolerance", p.pairwise.verification.fine_dimension_tolerance);
  if (pcl::console::parse_argument (argc, argv, "--checked-dimensions", p.pairwise.verification.checked_dimensions) >= 0)
    p.global_verification.checked_dimensions = p.pairwise.verification.checked_dimensions;
  pcl::console::setVerbosityLevel (pcl::console::L_ERROR);
  try
  {
    if (pcl::console::find_switch (argc, argv, "--dragon"))
    {
      auto params = options.params;
      params.loop = true;
      evaluateSet ("dragon", options.data + "/stanford/dragon_stand/dragonStandRight.conf", params, options);
    }
    if (pcl::console::find_switch (argc, argv, "--bunny"))
      evaluateSet ("bunny", options.data + "/stanford/bunny/bun.conf", options.params, options);
  }
  catch (const std::exception& e)
  {
    std::fprintf (stderr, "eval_multiview: %s\n", e.what ());
    return 2;
  }
  return 0;
}
