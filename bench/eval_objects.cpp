/*
 * eval_objects: pairwise registration on many objects, as a new user runs it (issue 23).
 *
 *   eval_objects [--real] [--meshes] [--objects a,b,...] [--truth] [options]   (see --help)
 *
 * Every pair of every set is registered as pcl_tensor_register registers it (the two raw scans, D
 * from the pair alone) and scored against the ground truth; the ground-truth pose is also handed to
 * local verification (true-pose recall: which check refuses it), and the pose's conditioning
 * (pcl::registration::computePoseConditioning) is measured at the truth and at the reported pose.
 * With --fpfh, PCL's FPFH + SampleConsensusPrerejective + the same ICP registers the same pairs, side by
 * side (bench/eval/fpfh_baseline.h). One CSV row per pair (objects_pairs.csv) and one summary line per
 * object (objects.csv).
 */
#include "eval/eval_main.h"
#include "eval/eval_views.h"
#include "eval/pair_evaluation.h"
#include "eval/pair_runs.h"

#include <pcl/common/time.h>
#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/io/scan_mesh_io.h>
#include <pcl/registration/correspondence_estimation_tensor.h>
#include <pcl/registration/pose_conditioning.h>
#include <pcl/simulation/example_object.h>
#include <pcl/simulation/view_set.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

using namespace pcl_tensor_eval;

namespace
{
  struct Options
  {
    std::string data = PCL_TENSOR_SHARED_DATA;
    std::string out = "bench_results";
    std::vector<std::string> objects;  ///< empty: every object
    bool real = false, meshes = false, truth = false;
    bool pushbroom = false, scanner = false;
    /** The 26 directions of the paper's synthetic set (pcl::makeDefaultViewDirections) instead of a ring. */
    bool all_around = false;
    /** Also PCL's FPFH + SampleConsensusPrerejective on every pair. */
    bool fpfh = false;
    FpfhBaselineParams baseline;
    int specks = -1;  ///< with --scanner: specks per view instead of the preset's (-1: the preset's)
    int ring = 12;
    double step = 30.0, noise = 0.3;
    int threads = 1;
    int max_pairs = 0;
    pcl::registration::TensorRegistrationParams params;
  };

  /** One pair: as the app registers it, and the verifier's verdict on its ground-truth pose. */
  struct ObjectPair
  {
    std::string object;
    PairResult result;
    bool ambiguous = false;
    double reported_conditioning = -1.0;  ///< at the reported pose; -1 when none was reported
    pcl::registration::TensorVerificationResult reported;  ///< the reported pose's verification
    pcl::registration::TensorCovisibility truth_covisibility, reported_covisibility;
    /** Free-space violations at margins of 2, 4 and 8 d_res (at least 3 sigma), at the truth and the reported pose. */
    std::array<double, 3> truth_violation{}, reported_violation{};
    pcl::registration::TensorVerificationResult truth;  ///< the ground truth, verified with D from the pair
    double truth_conditioning = -1.0;
    PairResult fpfh;  ///< PCL's FPFH baseline on the pair (with --fpfh)
    std::size_t hypotheses_tried = 0;  ///< verified up to the one reported, or all of them (TensorRegistrationReport)
  };

  void
  printHelp (const char* name)
  {
    const Options d;
    std::printf ("Pairwise registration on many objects, as pcl_tensor_register runs it (issue 23).\n\n"
                 "Usage: %s [--real] [--meshes] [options]\n\n"
                 "  --real             the Stanford scans with their .conf poses: bunny (bun.conf), dragon_stand\n"
                 "  --meshes           rendered rings of the shared meshes (meshes/*.ply), bun_zipper, dragon_vrip_res3\n"
                 "                     and the built-in example object\n"
                 "  --objects A,B      only these sets (names as printed: bunny, dragon_stand, teapot, example, ...)\n"
                 "  --truth            also verify every pair's ground-truth pose (true-pose recall) and measure the\n"
                 "                     conditioning at the truth\n"
                 "  --ring N           rendered views per ring (default %d)\n"
                 "  --all-around       the 26 directions of the paper's synthetic set instead of a ring\n"
                 "  --step DEG         azimuth step of the ring (default %g)\n"
                 "  --noise S          noise along the rays, sigma in d_res (default %g)\n"
                 "  --pushbroom        render with a pushbroom (line-scan) camera instead of a perspective one\n"
                 "  --scanner          render with scanner artifacts (pcl::scannerLikeArtifacts: dropout, holes, specks)\n"
                 "  --specks N         with --scanner: N specks per view instead of the preset's\n"
                 "  --threads N        pairs registered at once (default %d; times are per pair, one core each)\n"
                 "  --max-pairs N      only the first N pairs of each set, 0 = all (default %d)\n"
                 "  --fine-dimension-tolerance T   local verification after ICP: allowed excess over D in d_res (default %g)\n"
                 "  --fine-dimension-fraction F  ... or this fraction of mean(D), when larger (0: the paper's; default %g)\n"
                 "  --coarse-dimension-fraction F  before ICP: allowed excess over D as a fraction of mean(D) (default %g)\n"
                 "  --correspondence-fraction F  n_c = F min(|M_m|, |M_s|): correspondences before ICP, 2 n_c after (default %g)\n"
                 "  --empty-space-margin M  free-space check: points M d_res clear of the other view's surface count (0: off; default %g)\n"
                 "  --checked-dimensions N  largest principal extents the dimension checks compare with D (default %d)\n"
                 "  --no-rival-probe   do not probe rival poses (TensorRegistrationParams::probe_rivals)\n"
                 "  --rival-margin M   a rival with (1 - M) times the kept pose's fine correspondences is ambiguous (default %g)\n"
                 "  --rival-empty-space-margin M  dismiss rivals whose points lie where the other sensor saw nothing M d_res\n"
                 "                     from its surface (0: every rival doubts; default %g)\n"
                 "  --rival-dimension-factor F  a rival refused by D alone is judged with F times the dimension\n"
                 "                     tolerances (1: as answers are; default %g)\n"
                 "  --icp-normal-angle A  ICP pairs points whose normals differ by at most A degrees (180: all;\n"
                 "                     default %g) ...\n"
                 "  --rival-icp-normal-angle A  ... and the rivals' ICP by at most A (default %g)\n"
                 "  --tr T, --tc T     tensor matching thresholds t_r and t_c, Eq. 5 and 6 (default %g, %g)\n"
                 "  --fallback T       second round of matches over T for t_r and t_c (default %g; t_r, t_c or more: none)\n"
                 "  --order O          order of hypotheses: best or scene (default %s)\n"
                 "  --fpfh             also PCL's FPFH + SampleConsensusPrerejective + the same ICP on every pair (one\n"
                 "                     thread: PCL draws with std::rand)\n"
                 "  --out DIR          CSVs: objects_pairs.csv, objects.csv (default %s)\n"
                 "  --data DIR         third-party data (default %s)\n",
                 name, d.ring, d.step, d.noise, d.threads, d.max_pairs,
                 d.params.verification.fine_dimension_tolerance, d.params.verification.fine_dimension_fraction,
                 d.params.verification.coarse_dimension_fraction, d.params.verification.correspondence_fraction,
                 d.params.verification.empty_space_margin, d.params.verification.checked_dimensions, d.params.rival_margin,
                 d.params.rival_empty_space_margin, d.params.rival_dimension_factor,
                 d.params.verification.icp_max_normal_angle, d.params.rival_icp_max_normal_angle,
                 d.params.overlap_threshold, d.params.correlation_threshold, d.params.fallback_overlap_threshold,
                 pcl::registration::tensorMatchOrderName (d.params.order), d.out.c_str (), d.data.c_str ());
  }

  std::string
  stem (const std::string& path)
  {
    return std::filesystem::path (path).stem ().string ();
  }

  EvalViews
  ringViews (const pcl::ScanMesh& mesh, const Options& o)
  {
    pcl::SyntheticViewParams params;
    params.noise_sigma_resolutions = o.noise;
    params.camera.pushbroom = o.pushbroom;
    if (o.scanner)
      params.artifacts = pcl::scannerLikeArtifacts ();
    if (o.scanner && o.specks >= 0)
      params.artifacts.specks = o.specks;
    return makeSyntheticViews (mesh, params, o.all_around ? pcl::makeDefaultViewDirections () : pcl::makeRingViewDirections (o.ring, o.step));
  }

  /** Every set the options name, as (name, loader): loading waits until the set's turn. */
  std::vector<std::pair<std::string, std::function<EvalViews ()>>>
  objectSets (const Options& o)
  {
    std::vector<std::pair<std::string, std::function<EvalViews ()>>> sets;
    if (o.real)
    {
      sets.emplace_back ("bunny", [&o] { return loadStanfordViews (o.data + "/stanford/bunny/bun.conf"); });
      sets.emplace_back ("dragon_stand", [&o] { return loadStanfordViews (o.data + "/stanford/dragon_stand/dragonStandRight.conf"); });
    }
    if (o.meshes)
    {
      std::vector<std::string> meshes;
      for (const auto& entry : std::filesystem::directory_iterator (o.data + "/meshes"))
        if (entry.path ().extension () == ".ply")
          meshes.push_back (entry.path ().string ());
      std::sort (meshes.begin (), meshes.end ());
      meshes.push_back (o.data + "/stanford/bunny/bun_zipper.ply");
      meshes.push_back (o.data + "/stanford/dragon_recon/dragon_vrip_res3.ply");
      for (const auto& m : meshes)
        sets.emplace_back (stem (m), [&o, m] { return ringViews (pcl::io::loadScanMesh (m), o); });
      sets.emplace_back ("example", [&o] { return ringViews (pcl::makeExampleObject (), o); });
    }
    if (!o.objects.empty ())
      sets.erase (std::remove_if (sets.begin (), sets.end (), [&o] (const auto& s) {
                    return std::find (o.objects.begin (), o.objects.end (), s.first) == o.objects.end ();
                  }), sets.end ());
    return sets;
  }

  double
  conditioningAt (const EvalView& model, const EvalView& scene, const Eigen::Matrix4f& t, double d_res)
  {
    pcl::BoundedNearestSearch search (static_cast<float> (2.0 * d_res));
    search.setInputCloud (*model.prepared->fine.cloud);
    return pcl::registration::computePoseConditioning (*scene.prepared->fine.cloud, *model.prepared->fine.cloud, search, t,
                                                       2.0 * d_res).ratio;
  }

  /** The ground-truth pose handed to local verification, with D from the pair as the app takes it. */
  void
  verifyTruth (const EvalView& model, const EvalView& scene, const Options& o, ObjectPair& pair)
  {
    const pcl::ObjectDimensions dims = pcl::computeObjectDimensions<pcl::PointNormal> (
        std::vector<const pcl::PointCloud<pcl::PointNormal>*>{model.prepared->fine.cloud.get (), scene.prepared->fine.cloud.get ()});
    pcl::registration::CorrespondenceRejectorTensorVerification verification;
    setUpVerification (verification, model, scene, dims, o.params);
    verification.verify (groundTruth (model, scene).matrix ().cast<float> (), pair.truth);
    pair.truth_covisibility = verification.covisibility (pair.truth.transform);
    if (pair.result.registered)
      pair.reported_covisibility = verification.covisibility (pair.reported.transform);
    // The stage's margin (at least 2 d_res and 3 sigma), widened to 4 and 8 d_res.
    for (std::size_t k = 0; k < 3; ++k)
    {
      const double margin = std::max (verification.getFreeSpaceMargin (), (2 << k) * verification.getResolution ());
      pair.truth_violation[k] = verification.freeSpaceViolation (pair.truth.transform, margin);
      if (pair.result.registered)
        pair.reported_violation[k] = verification.freeSpaceViolation (pair.reported.transform, margin);
    }
    pair.truth_conditioning = conditioningAt (model, scene, pair.truth.transform, pair.result.resolution);
  }

  ObjectPair
  evaluatePair (const std::string& object, const EvalView& model, const EvalView& scene, const Options& o)
  {
    ObjectPair pair;
    pair.object = object;
    pcl::registration::TensorRegistrationReport report;
    pair.result = evaluateTensorRegistration (model, scene, o.params, &report);
    pair.result.overlap = pairOverlap (model, scene);
    pair.ambiguous = report.ambiguous;
    pair.reported = report.verification;
    pair.hypotheses_tried = report.hypotheses_tried;
    if (report.registered)
      pair.reported_conditioning = conditioningAt (model, scene, report.transform, pair.result.resolution);
    if (o.truth)
      verifyTruth (model, scene, o, pair);
    return pair;
  }

  /** Every pair of a set's views, or its first --max-pairs. */
  std::vector<std::pair<int, int>>
  objectPairs (const EvalViews& views, const Options& o)
  {
    auto pairs = allPairs (static_cast<int> (views.size ()));
    if (o.max_pairs > 0 && pairs.size () > static_cast<std::size_t> (o.max_pairs))
      pairs.resize (o.max_pairs);
    return pairs;
  }

  std::vector<ObjectPair>
  evaluateObject (const std::string& object, const EvalViews& views, const Options& o)
  {
    const auto pairs = objectPairs (views, o);
    std::vector<ObjectPair> rows (pairs.size ());
    std::atomic<std::size_t> next{0};
    std::mutex print;
    const auto work = [&] {
      for (std::size_t k; (k = next++) < pairs.size ();)
      {
        const auto& [m, s] = pairs[k];
        rows[k] = evaluatePair (object, views[m], views[s], o);
        const PairResult& r = rows[k].result;
        std::lock_guard<std::mutex> lock (print);
        std::printf ("  %s %s <- %s overlap %.2f: %s%s (%.1f deg, %.1f d_res) %.0f ms, conditioning %.3f; truth %s, %.3f\n",
                     object.c_str (), views[m].name.c_str (), views[s].name.c_str (), r.overlap,
                     r.correct ? "correct" : r.registered ? "WRONG" : "refused", rows[k].ambiguous ? " (ambiguous)" : "",
                     r.rotation_error_deg, r.translation_error_res, r.time_ms, rows[k].reported_conditioning,
                     o.truth ? toString (rows[k].truth.stage).c_str () : "-", rows[k].truth_conditioning);
      }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < o.threads; ++t)
      pool.emplace_back (work);
    work ();
    for (auto& t : pool)
      t.join ();
    if (o.fpfh)
    {
      // On this thread alone: SampleConsensusPrerejective draws from std::rand, seeded per pair.
      const auto fpfh = runFpfhPairs (views, computeFpfhViews (views, o.baseline), pairs, o.baseline, o.params.verification);
      for (std::size_t k = 0; k < rows.size (); ++k)
        rows[k].fpfh = fpfh[k];
    }
    return rows;
  }

  /** Overlap bands of the issue: >= 0.5, 0.3-0.5, 0.1-0.3, < 0.1. */
  int
  band (double overlap)
  {
    return overlap >= 0.5 ? 0 : overlap >= 0.3 ? 1 : overlap >= 0.1 ? 2 : 3;
  }

  double
  median (std::vector<double> v)
  {
    if (v.empty ())
      return 0.0;
    std::nth_element (v.begin (), v.begin () + v.size () / 2, v.end ());
    return v[v.size () / 2];
  }

  /** One summary line: correct/total and true-pose recall per band, wrong and ambiguous counts, the
    * checks that refused true poses, the conditioning ranges, the median time. */
  std::string
  summarize (const std::string& object, const std::vector<ObjectPair>& rows, bool truth, bool fpfh)
  {
    std::array<int, 4> total{}, correct{}, truth_passed{}, fpfh_correct{};
    int wrong = 0, ambiguous = 0, fpfh_wrong = 0;
    std::vector<double> fpfh_times;
    std::array<int, pcl::registration::kTensorVerificationStages> truth_refused{};
    double min_correct_cond = 1.0, max_wrong_cond = 0.0, min_truth_cond = 1.0;
    std::vector<double> times;
    for (const auto& p : rows)
    {
      const int b = band (p.result.overlap);
      ++total[b];
      correct[b] += p.result.correct;
      wrong += p.result.wrong ();
      ambiguous += p.ambiguous;
      times.push_back (p.result.time_ms);
      fpfh_correct[b] += p.fpfh.correct;
      fpfh_wrong += p.fpfh.wrong ();
      fpfh_times.push_back (p.fpfh.time_ms);
      if (p.result.correct)
        min_correct_cond = std::min (min_correct_cond, p.reported_conditioning);
      if (p.result.wrong ())
        max_wrong_cond = std::max (max_wrong_cond, p.reported_conditioning);
      if (truth && b < 3)
      {
        truth_passed[b] += p.truth.passed ();
        ++truth_refused[static_cast<int> (p.truth.stage)];
        min_truth_cond = std::min (min_truth_cond, p.truth_conditioning);
      }
    }
    std::ostringstream s;
    s << object;
    for (int b = 0; b < 4; ++b)
      s << ',' << correct[b] << '/' << total[b];
    s << ',' << wrong << ',' << ambiguous << ',' << median (times) / 1000.0;
    for (int b = 0; b < 3; ++b)
      s << ',' << (truth ? std::to_string (truth_passed[b]) + "/" + std::to_string (total[b]) : "-");
    for (std::size_t k = 1; k < truth_refused.size (); ++k)
      s << ',' << truth_refused[k];
    s << ',' << min_correct_cond << ',' << max_wrong_cond << ',' << (truth ? min_truth_cond : -1.0);
    for (int b = 0; b < 4; ++b)
      s << ',' << (fpfh ? std::to_string (fpfh_correct[b]) + "/" + std::to_string (total[b]) : "-");
    s << ',' << (fpfh ? std::to_string (fpfh_wrong) : "-") << ',' << (fpfh ? median (fpfh_times) / 1000.0 : -1.0);
    return s.str ();
  }

  std::string
  summaryHeader ()
  {
    std::string h = "object,correct_ge0.5,correct_0.3-0.5,correct_0.1-0.3,correct_lt0.1,wrong,ambiguous,median_s,"
                    "truth_ge0.5,truth_0.3-0.5,truth_0.1-0.3";
    for (std::size_t k = 1; k < pcl::registration::kTensorVerificationStages; ++k)
      h += ",truth_refused_" + toString (static_cast<pcl::registration::TensorVerificationStage> (k));
    return h + ",min_conditioning_correct,max_conditioning_wrong,min_conditioning_truth,"
               "fpfh_ge0.5,fpfh_0.3-0.5,fpfh_0.1-0.3,fpfh_lt0.1,fpfh_wrong,fpfh_median_s";
  }

  void
  writePairs (std::ofstream& out, const std::vector<ObjectPair>& rows)
  {
    for (const auto& p : rows)
    {
      const PairResult& r = p.result;
      out << p.object << ',' << r.model << ',' << r.scene << ',' << r.overlap << ',' << r.registered << ',' << r.correct << ','
          << p.ambiguous << ',' << r.rotation_error_deg << ',' << r.translation_error_res << ',' << r.time_ms << ','
          << p.reported_conditioning << ',' << toString (p.truth.stage) << ',' << p.truth.fine_dimension_excess << ','
          << p.truth.free_space_violation << ',' << p.truth_conditioning << ',' << p.reported.fine_correspondences << ','
          << p.reported.required_correspondences << ',' << p.reported.fine_dimension_excess << ','
          << p.reported.free_space_violation;
      for (const auto& c : {p.truth_covisibility, p.reported_covisibility})
        out << ',' << c.model_seen << ',' << c.scene_seen << ',' << c.model_matched << ',' << c.scene_matched;
      for (const auto& v : {p.truth_violation, p.reported_violation})
        out << ',' << v[0] << ',' << v[1] << ',' << v[2];
      out << ',' << p.fpfh.registered << ',' << p.fpfh.correct << ',' << p.fpfh.rotation_error_deg << ','
          << p.fpfh.translation_error_res << ',' << p.fpfh.time_ms << ',' << p.hypotheses_tried << ','
          << p.truth.fine_correspondences << ',' << p.truth.required_correspondences << ',' << p.truth.icp_abandoned << '\n';
    }
    out.flush ();
  }

  std::vector<std::string>
  splitList (const std::string& list)
  {
    std::vector<std::string> items;
    std::stringstream s (list);
    for (std::string item; std::getline (s, item, ',');)
      if (!item.empty ())
        items.push_back (item);
    return items;
  }

  Options
  parseOptions (int argc, char** argv)
  {
    Options o;
    pcl::console::parse_argument (argc, argv, "--data", o.data);
    pcl::console::parse_argument (argc, argv, "--out", o.out);
    o.real = pcl::console::find_switch (argc, argv, "--real");
    o.meshes = pcl::console::find_switch (argc, argv, "--meshes");
    o.truth = pcl::console::find_switch (argc, argv, "--truth");
    std::string objects;
    if (pcl::console::parse_argument (argc, argv, "--objects", objects) >= 0)
      o.objects = splitList (objects);
    pcl::console::parse_argument (argc, argv, "--ring", o.ring);
    pcl::console::parse_argument (argc, argv, "--step", o.step);
    pcl::console::parse_argument (argc, argv, "--noise", o.noise);
    o.pushbroom = pcl::console::find_switch (argc, argv, "--pushbroom");
    o.scanner = pcl::console::find_switch (argc, argv, "--scanner");
    o.all_around = pcl::console::find_switch (argc, argv, "--all-around");
    o.fpfh = pcl::console::find_switch (argc, argv, "--fpfh");
    pcl::console::parse_argument (argc, argv, "--specks", o.specks);
    pcl::console::parse_argument (argc, argv, "--threads", o.threads);
    pcl::console::parse_argument (argc, argv, "--max-pairs", o.max_pairs);
    auto& v = o.params.verification;
    pcl::console::parse_argument (argc, argv, "--fine-dimension-tolerance", v.fine_dimension_tolerance);
    pcl::console::parse_argument (argc, argv, "--fine-dimension-fraction", v.fine_dimension_fraction);
    pcl::console::parse_argument (argc, argv, "--coarse-dimension-fraction", v.coarse_dimension_fraction);
    pcl::console::parse_argument (argc, argv, "--correspondence-fraction", v.correspondence_fraction);
    pcl::console::parse_argument (argc, argv, "--empty-space-margin", v.empty_space_margin);
    pcl::console::parse_argument (argc, argv, "--checked-dimensions", v.checked_dimensions);
    pcl::console::parse_argument (argc, argv, "--rival-margin", o.params.rival_margin);
    pcl::console::parse_argument (argc, argv, "--rival-empty-space-margin", o.params.rival_empty_space_margin);
    pcl::console::parse_argument (argc, argv, "--rival-dimension-factor", o.params.rival_dimension_factor);
    pcl::console::parse_argument (argc, argv, "--icp-normal-angle", v.icp_max_normal_angle);
    pcl::console::parse_argument (argc, argv, "--rival-icp-normal-angle", o.params.rival_icp_max_normal_angle);
    pcl::console::parse_argument (argc, argv, "--tr", o.params.overlap_threshold);
    pcl::console::parse_argument (argc, argv, "--tc", o.params.correlation_threshold);
    if (pcl::console::parse_argument (argc, argv, "--fallback", o.params.fallback_overlap_threshold) >= 0)
      o.params.fallback_correlation_threshold = o.params.fallback_overlap_threshold;
    std::string order;
    if (pcl::console::parse_argument (argc, argv, "--order", order) >= 0)
      o.params.order = pcl::registration::parseTensorMatchOrder (order);
    o.params.probe_rivals = !pcl::console::find_switch (argc, argv, "--no-rival-probe");
    return o;
  }
}

int
main (int argc, char** argv)
{
  return evalMain (argc, argv, "eval_objects", printHelp, [] (int argc, char** argv) {
    const Options o = parseOptions (argc, argv);
    pcl::console::setVerbosityLevel (pcl::console::L_ERROR);
    std::filesystem::create_directories (o.out);
    std::ofstream pairs_csv (o.out + "/objects_pairs.csv"), summary_csv (o.out + "/objects.csv");
    pairs_csv << "object,model,scene,overlap,registered,correct,ambiguous,rotation_error_deg,translation_error_res,time_ms,"
                 "conditioning,truth_stage,truth_fine_dimension_excess,truth_free_space,truth_conditioning,"
                 "fine_correspondences,required_correspondences,fine_dimension_excess,free_space,"
                 "truth_model_seen,truth_scene_seen,truth_model_matched,truth_scene_matched,"
                 "model_seen,scene_seen,model_matched,scene_matched,"
                 "truth_free_space_2,truth_free_space_4,truth_free_space_8,free_space_2,free_space_4,free_space_8,"
                 "fpfh_registered,fpfh_correct,fpfh_rotation_error_deg,fpfh_translation_error_res,fpfh_time_ms,"
                 "hypotheses_tried,truth_fine_correspondences,truth_required_correspondences,truth_icp_abandoned\n";
    summary_csv << summaryHeader () << '\n';
    std::printf ("%s\n", summaryHeader ().c_str ());
    for (const auto& [name, load] : objectSets (o))
    {
      EvalViews views = load ();
      prepareViews (views, o.params);
      const auto rows = evaluateObject (name, views, o);
      writePairs (pairs_csv, rows);
      const std::string line = summarize (name, rows, o.truth, o.fpfh);
      summary_csv << line << '\n';
      summary_csv.flush ();
      std::printf ("SUMMARY %s\n", line.c_str ());
    }
    return 0;
  });
}
