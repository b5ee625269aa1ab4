/*
 * eval_paper: the experiments of the paper's Sections 3, 7 and 8 (issue 8), beside PCL's FPFH baseline.
 *
 *   eval_paper --all [--quick] [--out DIR]        (see --help; scripts/experiments.sh runs it and plots)
 *
 * Each experiment writes its CSVs into --out and a summary_<experiment>.csv of rows "the paper's
 * figure | ours | baseline", from which scripts/experiments.sh writes doc/results.md.
 */
#include "eval/eval_main.h"
#include "eval/eval_views.h"
#include "eval/fpfh_baseline.h"
#include "eval/descriptor_discrimination.h"
#include "eval/frame_stability.h"
#include "eval/pair_evaluation.h"
#include "eval/pair_runs.h"
#include "eval/pair_summary.h"
#include "eval/paper_summary.h"

#include <pcl/common/time.h>
#include <pcl/console/parse.h>
#include <pcl/io/scan_mesh_io.h>
#include <pcl/registration/correspondence_estimation_tensor.h>
#include <pcl/simulation/example_object.h>
#include <pcl/simulation/view_set.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <functional>
#include <fstream>
#include <map>
#include <random>

using namespace pcl_tensor_eval;

namespace
{
  /** --quick: pairs per object and experiment. */
  constexpr int kQuickPairs = 4;

  /** Pairs whose Eq. 14 overlap is at least this are "overlapping" (Section 7.4: 50% ensures success). */
  constexpr double kOverlapping = 0.5;

  /** Everything the command line sets. */
  struct Options
  {
    std::string data = PCL_TENSOR_SHARED_DATA;
    std::string out = "doc/results";
    pcl::registration::TensorRegistrationParams params;
    FpfhBaselineParams baseline;
    /** Pairs per object and experiment, spread evenly over the list (real pairs: sorted by overlap);
      * 0: every pair. --quick sets kQuickPairs. */
    int max_pairs = 0;
    /** Hypotheses at most in the scene-order run of the efficiency experiment (refuted hypotheses
      * dominate its time, so the cap is the best-first run's; doc/design.md#hypothesis-cap-and-repeats). */
    int scene_order_hypotheses = 300;
  };

  /** The experiments selected on the command line. */
  struct Selection
  {
    bool overlap = false, baseline = false, efficiency = false, stability = false, resolution = false;
    bool accuracy = false, noise = false, spin = false, discrimination = false;
    bool real () const { return overlap || baseline || efficiency || stability || resolution || spin || discrimination; }
  };

  void
  printHelp (const char* name)
  {
    const Options d;
    std::printf ("The paper's experiments (Mian et al., IJCV 2006, Sections 3, 7 and 8) beside PCL's FPFH baseline.\n\n"
                 "Usage: %s [--all] [experiments] [options]\n\n"
                 "Experiments (real scans: every pair of the bunny scans of bun.conf and the dragon scans of\n"
                 "dragonStandRight.conf; synthetic: 26 views, adjacent pairs 30 deg apart):\n"
                 "  --efficiency   Fig. 17, Eq. 13: tensors of M'_s matched before success (scene order), hypotheses\n"
                 "                 tried (best first), theta_d index against all-against-all, on overlapping pairs\n"
                 "  --overlap      Fig. 18: success against overlap (Eq. 14) over every pair\n"
                 "  --baseline     FPFH + SampleConsensusPrerejective + the same ICP on every pair\n"
                 "  --accuracy     Fig. 13: rotation and translation errors, synthetic bun_zipper, dragon_vrip_res3, example object\n"
                 "  --noise        Section 7.5: synthetic bunny with sigma = 0..4 d_res along the viewing direction\n"
                 "  --stability    Section 3, Figs. 4-5, Eq. 4: vertices recurring before and after reduction to 400 faces,\n"
                 "                 frames of corresponding vertex pairs within 5 and 10 deg of the ground truth\n"
                 "  --resolution   Figs. 15-16: success on overlapping pairs at 100..1000 faces and 100..700 tensors per view\n"
                 "  --spin         Fig. 20: pcl::SpinImageEstimation (width 8) on the same reduced meshes, grouped as Johnson\n"
                 "                 and Hebert do, with the same verification, at 100..1000 faces\n"
                 "  --discrimination  Fig. 21: 700 descriptors per view (2000 faces), best 200 matches, ground-truth displacement\n"
                 "                 in bins (bin = the reduced mesh's resolution): tensors 15^3 against spin images width 8\n"
                 "  --all          every experiment above\n\n"
                 "Options:\n"
                 "  --quick        %d pairs per object and experiment (development; same as --pairs %d)\n"
                 "  --pairs N      N pairs per object and experiment, spread evenly over the pairs sorted by overlap\n"
                 "                 (synthetic: over the adjacent pairs); 0 = every pair (default)\n"
                 "  --out DIR      CSVs and summaries (default %s)\n"
                 "  --data DIR     third-party data (default %s)\n"
                 "  --max-hypotheses N   tensor method's cap (default %d)\n"
                 "  --scene-batches N    tensor method: the scene's tensors in N batches, each verified before the next (default %d)\n"
                 "  --faces N      tensor method: faces per reduced mesh (default %d)\n"
                 "  --count-scene-only   tensor method: verification counts the scene's correspondences only\n"
                 "                 (TensorVerificationParams::count_both_views off; default: both views)\n"
                 "  --checked-dimensions N  largest principal extents local verification compares with D (default %d)\n",
                 name, kQuickPairs, kQuickPairs, d.out.c_str (), d.data.c_str (), d.params.max_hypotheses,
                 d.params.scene_tensor_batches, d.params.preparation.target_faces, d.params.verification.checked_dimensions);
  }

  Options
  parseOptions (int argc, char** argv)
  {
    using pcl::console::parse_argument;
    Options o;
    parse_argument (argc, argv, "--out", o.out);
    parse_argument (argc, argv, "--data", o.data);
    parse_argument (argc, argv, "--max-hypotheses", o.params.max_hypotheses);
    parse_argument (argc, argv, "--scene-batches", o.params.scene_tensor_batches);
    parse_argument (argc, argv, "--faces", o.params.preparation.target_faces);
    parse_argument (argc, argv, "--pairs", o.max_pairs);
    if (pcl::console::find_switch (argc, argv, "--quick"))
      o.max_pairs = kQuickPairs;
    if (pcl::console::find_switch (argc, argv, "--count-scene-only"))
      o.params.verification.count_both_views = false;
    parse_argument (argc, argv, "--checked-dimensions", o.params.verification.checked_dimensions);
    return o;
  }

  Selection
  parseSelection (int argc, char** argv)
  {
    const auto on = [&] (const char* flag) { return pcl::console::find_switch (argc, argv, flag) || pcl::console::find_switch (argc, argv, "--all"); };
    Selection s;
    s.baseline = on ("--baseline");
    s.overlap = on ("--overlap");
    s.efficiency = on ("--efficiency");
    s.stability = on ("--stability");
    s.resolution = on ("--resolution");
    s.accuracy = on ("--accuracy");
    s.noise = on ("--noise");
    s.spin = on ("--spin");
    s.discrimination = on ("--discrimination");
    return s;
  }

  std::vector<std::pair<int, int>>
  limited (std::vector<std::pair<int, int>> pairs, const Options& o)
  {
    const std::size_t n = static_cast<std::size_t> (o.max_pairs);
    if (n == 0 || pairs.size () <= n)
      return pairs;
    std::vector<std::pair<int, int>> spread;
    for (std::size_t i = 0; i < n; ++i)
      spread.push_back (pairs[n == 1 ? 0 : i * (pairs.size () - 1) / (n - 1)]);
    return spread;
  }

  /** One object's real scans, prepared, with the overlap of every pair. */
  struct RealObject
  {
    std::string label;
    EvalViews views;
    pcl::ObjectDimensions dims;
    std::vector<std::pair<int, int>> pairs;
    std::vector<double> overlaps;  ///< of pairs, in order

    /** Every pair, by increasing overlap. */
    std::vector<std::pair<int, int>>
    byOverlap (double min_overlap = -1.0) const
    {
      std::vector<std::size_t> order;
      for (std::size_t i = 0; i < pairs.size (); ++i)
        if (overlaps[i] >= min_overlap)
          order.push_back (i);
      std::stable_sort (order.begin (), order.end (), [&] (std::size_t a, std::size_t b) { return overlaps[a] < overlaps[b]; });
      std::vector<std::pair<int, int>> sorted;
      for (std::size_t i : order)
        sorted.push_back (pairs[i]);
      return sorted;
    }

    /** The pairs with overlap >= kOverlapping, by increasing overlap. */
    std::vector<std::pair<int, int>>
    overlapping () const
    {
      return byOverlap (kOverlapping);
    }
  };

  RealObject
  loadRealObject (const std::string& label, const std::string& conf, const Options& o)
  {
    std::printf ("\n== %s: loading and preparing %s\n", label.c_str (), conf.c_str ());
    RealObject object;
    object.label = label;
    object.views = loadStanfordViews (conf);
    object.dims = prepareViews (object.views, o.params);
    printViews (object.views, object.dims);
    object.pairs = allPairs (static_cast<int> (object.views.size ()));
    for (const auto& [m, s] : object.pairs)
      object.overlaps.push_back (pairOverlap (object.views[m], object.views[s]));
    std::printf ("  %zu pairs, %zu with overlap >= %.1f\n", object.pairs.size (), object.overlapping ().size (), kOverlapping);
    return object;
  }

  std::vector<RealObject>
  loadRealObjects (const Options& o)
  {
    std::vector<RealObject> objects;
    objects.push_back (loadRealObject ("bunny", o.data + "/stanford/bunny/bun.conf", o));
    objects.push_back (loadRealObject ("dragon", o.data + "/stanford/dragon_stand/dragonStandRight.conf", o));
    return objects;
  }

  std::vector<PairResult>
  concat (const std::vector<std::vector<PairResult>>& parts)
  {
    std::vector<PairResult> all;
    for (const auto& p : parts)
      all.insert (all.end (), p.begin (), p.end ());
    return all;
  }

  std::vector<double>
  times (const std::vector<PairResult>& results)
  {
    std::vector<double> t;
    for (const PairResult& r : results)
      t.push_back (r.time_ms);
    return t;
  }

  // ---------------------------------------------------------------- Fig. 18 and the FPFH baseline

  /** The rows of one method over every pair: success by overlap band, false accepts, time. The
    * tensor method's go into the tensor column, the baseline's into the FPFH column, with the same
    * figure and quantity, so that doc/results.md can put them side by side. */
  void
  addOverlapRows (std::vector<SummaryRow>& rows, const std::string& label, const std::vector<PairResult>& results, bool fpfh)
  {
    const auto correct = [] (const PairResult& r) { return r.correct; };
    const auto wrong = [] (const PairResult& r) { return r.wrong (); };
    const auto registered = [] (const PairResult& r) { return r.registered; };
    const auto band = [&] (double lo, double hi, const auto& pred) {
      const auto in = inOverlap (results, lo, hi);
      return fractionText (countIf (in, pred), in.size ());
    };
    const auto add = [&] (const std::string& figure, const std::string& quantity, const std::string& paper, const std::string& value) {
      rows.push_back ({figure, label + ": " + quantity, paper, fpfh ? "" : value, fpfh ? value : "", ""});
    };
    add ("Fig. 18", "correct at overlap >= 0.5", "~100%", band (0.5, 2.0, correct));
    add ("Fig. 18", "correct at overlap 0.3-0.5", "varies by object", band (0.3, 0.5, correct));
    add ("Fig. 18", "correct at overlap 0.1-0.3", "mostly fails", band (0.1, 0.3, correct));
    add ("Sec. 4.1", "wrong registrations reported / all pairs", "-", band (-1.0, 2.0, wrong));
    add ("Sec. 4.1", "false accepts at overlap < 0.1 (registered / pairs)", "-", band (-1.0, 0.1, registered));
    add ("Sec. 7.3", "median time per pair after per-view features (ms)", "-", numberText (median (times (results)), 0));
    if (!fpfh)
    {
      std::vector<double> hypotheses;
      for (const PairResult& r : inOverlap (results, kOverlapping, 2.0))
        if (r.correct)
          hypotheses.push_back (static_cast<double> (r.hypotheses));
      add ("Fig. 17a", "hypotheses verified before success (best first; correct pairs with overlap >= 0.5; median)", "-",
           numberText (median (hypotheses), 0));
    }
  }

  /** Fig. 18: the tensor method (or, with \a fpfh, the baseline) on every pair of every object. */
  void
  runOverlap (const std::vector<RealObject>& objects, bool fpfh, const Options& o)
  {
    const std::string method = fpfh ? "fpfh" : "tensor";
    std::vector<SummaryRow> rows;
    std::vector<std::vector<PairResult>> all;
    for (std::size_t k = 0; k < objects.size (); ++k)
    {
      const RealObject& object = objects[k];
      const auto pairs = limited (object.byOverlap (), o);
      std::printf ("\n== Fig. 18, %s: %s on %zu pairs\n", object.label.c_str (), method.c_str (), pairs.size ());
      if (fpfh)
        all.push_back (runFpfhPairs (object.views, computeFpfhViews (object.views, o.baseline), pairs, o.baseline,
                                     o.params.verification));
      else
        all.push_back (runTensorPairs (object.views, object.dims, pairs, o.params));
      writePairCsv (o.out + "/overlap_" + object.label + "_" + method + ".csv", all.back ());
      appendOverlapBins (o.out + "/overlap_bins_" + method + ".csv", object.label + "_" + method, all.back (), 0.1, k == 0);
      addOverlapRows (rows, object.label, all.back (), fpfh);
    }
    const auto results = concat (all);
    addOverlapRows (rows, "bunny + dragon", results, fpfh);
    writeSummaryCsv (o.out + (fpfh ? "/summary_baseline.csv" : "/summary_overlap.csv"), rows);
    printPairSummary ("every real pair, " + method, results);
  }

  // ---------------------------------------------------------------- Fig. 17 and Eq. 13

  /** Comparisons and time of matching one pair, with or without the theta_d index. */
  struct MatchingCost
  {
    std::size_t comparisons = 0;
    double ms = 0.0;
  };

  MatchingCost
  matchingCost (const EvalView& model, const EvalView& scene, const Options& o, bool index)
  {
    pcl::registration::CorrespondenceEstimationTensor matcher = tensorMatcher (o.params);
    matcher.setUseThetaIndex (index);
    matcher.setInputSource (scene.tensors);
    matcher.setInputTarget (model.tensors);
    pcl::Correspondences correspondences;
    pcl::StopWatch watch;
    matcher.determineCorrespondences (correspondences);
    return {matcher.getComparisons (), watch.getTime ()};
  }

  /** Histogram of theta_d of every tensor of every view, in bins of Delta theta_d (Fig. 17b). */
  std::vector<double>
  thetaHistogram (const std::vector<RealObject>& objects, double width)
  {
    std::vector<double> p (static_cast<std::size_t> (std::ceil (180.0 / width)), 0.0);
    double total = 0.0;
    for (const RealObject& object : objects)
      for (const EvalView& v : object.views)
        for (const pcl::TensorDescriptor& t : *v.tensors)
        {
          p[std::min (p.size () - 1, static_cast<std::size_t> (t.theta_d / width))] += 1.0;
          total += 1.0;
        }
    for (double& x : p)
      x /= total;
    return p;
  }

  /** Eq. 13 with the measured theta_d distribution: n_t^2 / mu, mu = n_t^2 sum_i p_i (p_i-1 + p_i + p_i+1). */
  double
  predictedIndexSpeedup (const std::vector<double>& p)
  {
    double fraction = 0.0;
    for (std::size_t i = 0; i < p.size (); ++i)
      fraction += p[i] * (p[i] + (i > 0 ? p[i - 1] : 0.0) + (i + 1 < p.size () ? p[i + 1] : 0.0));
    return 1.0 / fraction;
  }

  void
  runEfficiency (const std::vector<RealObject>& objects, const Options& o)
  {
    std::ofstream csv (o.out + "/efficiency.csv");
    csv << "object,model,scene,overlap,registered_scene_order,correct_scene_order,scene_tensors_matched,"
           "hypotheses_scene_order,matches,model_tensors,scene_tensors,"
           "comparisons_index,comparisons_all,matching_ms_index,matching_ms_all\n";
    std::vector<double> scene_tensors_matched;
    double comparisons_index = 0, comparisons_all = 0, ms_index = 0, ms_all = 0;
    std::size_t pairs_total = 0, correct_scene = 0;
    pcl::registration::TensorRegistrationParams scene_order = o.params;
    scene_order.order = pcl::registration::TensorMatchOrder::SCENE_ORDER;
    scene_order.max_hypotheses = o.scene_order_hypotheses;
    for (const RealObject& object : objects)
    {
      const auto pairs = limited (object.overlapping (), o);
      std::printf ("\n== Fig. 17, %s: %zu pairs with overlap >= %.1f, scene order\n", object.label.c_str (), pairs.size (),
                   kOverlapping);
      for (const auto& [model_index, scene_index] : pairs)
      {
        const EvalView& m = object.views[model_index];
        const EvalView& s = object.views[scene_index];
        // In scene order, the winning match's scene tensor is how many tensors of M'_s were matched.
        pcl::registration::TensorRegistrationReport report;
        PairResult by_scene = evaluateTensorPair (m, s, object.dims, scene_order, &report);
        by_scene.overlap = pairOverlap (m, s);
        const long matched = report.registered ? report.winning_match.scene + 1 : -1;
        std::printf ("  scene order: %-9s <- %-9s %-14s scene tensors matched %ld, hypotheses %zu\n", m.name.c_str (),
                     s.name.c_str (), by_scene.correct ? "correct" : by_scene.registered ? "WRONG" : "not registered", matched,
                     by_scene.hypotheses);
        const MatchingCost with = matchingCost (m, s, o, true), without = matchingCost (m, s, o, false);
        csv << object.label << ',' << m.name << ',' << s.name << ',' << by_scene.overlap << ',' << by_scene.registered << ','
            << by_scene.correct << ',' << matched << ',' << by_scene.hypotheses << ',' << by_scene.matches << ','
            << m.tensors->size () << ',' << s.tensors->size () << ','
            << with.comparisons << ',' << without.comparisons << ',' << with.ms << ',' << without.ms << '\n';
        if (by_scene.correct)
          scene_tensors_matched.push_back (static_cast<double> (matched));
        correct_scene += by_scene.correct;
        comparisons_index += static_cast<double> (with.comparisons);
        comparisons_all += static_cast<double> (without.comparisons);
        ms_index += with.ms;
        ms_all += without.ms;
        ++pairs_total;
      }
    }
    const std::vector<double> p = thetaHistogram (objects, o.params.theta_bin_width);
    std::ofstream theta (o.out + "/theta_pdf.csv");
    theta << "theta_lo_deg,probability\n";
    for (std::size_t i = 0; i < p.size (); ++i)
      theta << i * o.params.theta_bin_width << ',' << p[i] << '\n';

    std::vector<SummaryRow> rows;
    rows.push_back ({"Fig. 17a", "tensors of M's matched before success (scene order; median over correct pairs)", "26",
                     numberText (median (scene_tensors_matched), 0), "", ""});
    rows.push_back ({"Fig. 17a", "correct pairs in scene order (overlap >= 0.5; best first: see the overlap table)", "-",
                     fractionText (correct_scene, pairs_total), "", ""});
    rows.push_back ({"Eq. 13", "index speed-up predicted from the theta_d distribution (n_t^2 / mu)", "6.2",
                     numberText (predictedIndexSpeedup (p), 1), "", ""});
    rows.push_back ({"Eq. 13", "index speed-up measured: comparisons all-against-all / with index", "6.2",
                     numberText (comparisons_all / comparisons_index, 1), "", ""});
    rows.push_back ({"Eq. 13", "index speed-up measured: matching time all-against-all / with index", "6.2",
                     numberText (ms_all / ms_index, 1), "", ""});
    writeSummaryCsv (o.out + "/summary_efficiency.csv", rows);
    for (const SummaryRow& r : rows)
      std::printf ("  %-90s paper %-6s ours %s\n", r.quantity.c_str (), r.paper.c_str (), r.tensor.c_str ());
  }

  // ---------------------------------------------------------------- Section 3, Figs. 4-5, Eq. 4

  /** Sums of Section 3's measurements over the pairs of one object. */
  struct StabilityTotals
  {
    double fine = 0.0, reduced = 0.0;
    std::size_t pairs = 0, tensors = 0, within5 = 0, within10 = 0, near = 0, vertices = 0;

    void
    add (const FrameStability& f)
    {
      ++pairs;
      fine += f.overlap_fine;
      reduced += f.overlap_reduced;
      tensors += f.corresponding_tensors;
      within5 += f.frames_within_5deg;
      within10 += f.frames_within_10deg;
      vertices += f.nearest_vertex_res.size ();
      near += static_cast<std::size_t> (std::count_if (f.nearest_vertex_res.begin (), f.nearest_vertex_res.end (),
                                                       [] (double d) { return d <= 4.0; }));
    }
  };

  void
  addStabilityRows (std::vector<SummaryRow>& rows, const std::string& label, const StabilityTotals& t, const StabilityTotals& loose)
  {
    const double n = static_cast<double> (std::max<std::size_t> (t.pairs, 1));
    const std::string on = label + " (" + std::to_string (t.pairs) + " pairs with overlap >= 0.5)";
    rows.push_back ({"Sec. 3", on + ": mean fraction of vertices with a counterpart within 2 d_res; fine meshes M_i", "60% (dog)",
                     numberText (100.0 * t.fine / n, 1) + "%", "", ""});
    rows.push_back ({"Sec. 3", on + ": ... reduced meshes M'_i (400 faces)", "41.8% (dog)", numberText (100.0 * t.reduced / n, 1) + "%", "", ""});
    rows.push_back ({"Sec. 3", on + ": ... ratio reduced / fine", "0.7 (dog)", numberText (t.reduced / std::max (t.fine, 1e-12), 2), "", ""});
    rows.push_back ({"Fig. 4d", on + ": reduced scene vertices with a reduced model vertex within 4 d_res", "almost all (dog: 2.8 cm)",
                     fractionText (t.near, t.vertices), "", ""});
    rows.push_back ({"Eq. 4", on + ": tensor pairs on vertices corresponding within 2 d_res whose frames agree within 5 deg", "-",
                     fractionText (t.within5, t.tensors), "", ""});
    rows.push_back ({"Eq. 4", on + ": ... within 10 deg", "-", fractionText (t.within10, t.tensors), "", ""});
    rows.push_back ({"Eq. 4", on + ": tensor pairs on vertices corresponding within 6 d_res whose frames agree within 5 deg", "-",
                     fractionText (loose.within5, loose.tensors), "", ""});
    rows.push_back ({"Eq. 4", on + ": ... within 10 deg", "-", fractionText (loose.within10, loose.tensors), "", ""});
  }

  void
  runStability (const std::vector<RealObject>& objects, const Options& o)
  {
    // The paper's experiment reduces to about 400 faces (Section 3), not the pipeline's 1000.
    pcl::registration::TensorRegistrationParams params = o.params;
    params.preparation.target_faces = 400;
    // The verification's coarse distance: how far apart vertices may be and still give a usable frame.
    const double loose_resolutions = o.params.verification.coarse_distance;
    std::ofstream csv (o.out + "/stability.csv");
    csv << "object,model,scene,overlap_fine,overlap_reduced,reduced_model_vertices,reduced_scene_vertices,"
           "corresponding_tensors,frames_within_5deg,frames_within_10deg\n";
    std::ofstream distances (o.out + "/stability_distances.csv");
    distances << "object,nearest_vertex_res\n";
    std::ofstream frames (o.out + "/stability_frames.csv");
    frames << "object,vertex_distance_res,frame_error_deg\n";
    std::vector<SummaryRow> rows;
    for (const RealObject& object : objects)
    {
      EvalViews views = object.views;
      prepareViews (views, params);
      StabilityTotals strict, loose;
      for (const auto& [m, s] : limited (object.overlapping (), o))
      {
        const FrameStability f = measureFrameStability (views[m], views[s]);
        const FrameStability l = measureFrameStability (views[m], views[s], loose_resolutions);
        csv << object.label << ',' << f.model << ',' << f.scene << ',' << f.overlap_fine << ',' << f.overlap_reduced << ','
            << f.reduced_model_vertices << ',' << f.reduced_scene_vertices << ',' << f.corresponding_tensors << ','
            << f.frames_within_5deg << ',' << f.frames_within_10deg << '\n';
        for (double d : f.nearest_vertex_res)
          distances << object.label << ',' << d << '\n';
        for (double e : f.frame_error_deg)
          frames << object.label << ',' << kCorrespondingVertexResolutions << ',' << e << '\n';
        for (double e : l.frame_error_deg)
          frames << object.label << ',' << loose_resolutions << ',' << e << '\n';
        std::printf ("  %s %-9s <- %-9s overlap fine %.3f reduced %.3f; corresponding tensors %zu (%zu within 10 deg), "
                     "within %g d_res %zu (%zu)\n", object.label.c_str (), f.model.c_str (), f.scene.c_str (), f.overlap_fine,
                     f.overlap_reduced, f.corresponding_tensors, f.frames_within_10deg, loose_resolutions,
                     l.corresponding_tensors, l.frames_within_10deg);
        strict.add (f);
        loose.add (l);
      }
      addStabilityRows (rows, object.label, strict, loose);
    }
    writeSummaryCsv (o.out + "/summary_stability.csv", rows);
  }

  // ---------------------------------------------------------------- Figs. 15-16

  /** Keep \a count tensors of each view, drawn with a fixed seed (all of them when there are fewer). */
  void
  subsampleTensors (EvalViews& views, std::size_t count, std::uint32_t seed)
  {
    std::mt19937 rng (seed);
    for (EvalView& v : views)
    {
      if (v.tensors->size () <= count)
        continue;
      std::vector<std::size_t> order (v.tensors->size ());
      for (std::size_t i = 0; i < order.size (); ++i)
        order[i] = i;
      std::shuffle (order.begin (), order.end (), rng);
      order.resize (count);
      std::sort (order.begin (), order.end ());
      pcl::PointCloud<pcl::TensorDescriptor>::Ptr kept (new pcl::PointCloud<pcl::TensorDescriptor>);
      for (std::size_t i : order)
        kept->push_back ((*v.tensors)[i]);
      v.tensors = kept;
    }
  }

  /** Correct and wrong registrations of one method on the overlapping pairs of one object. */
  struct PointCounts
  {
    std::size_t pairs = 0, correct = 0, wrong = 0;
  };

  using PairMethod = std::function<std::vector<PairResult> (const EvalViews&, const RealObject&, const std::vector<std::pair<int, int>>&)>;

  /** One point of Figs. 15, 16 or 20: \a method on the overlapping pairs of every object, one CSV row per object and one for all. */
  PointCounts
  sweepPoint (const std::string& sweep, int value, const std::string& method_name, const PairMethod& method,
              const std::vector<RealObject>& objects, const std::vector<EvalViews>& views, const Options& o, std::ofstream& csv)
  {
    PointCounts all;
    std::vector<double> descriptors;
    for (std::size_t k = 0; k < objects.size (); ++k)
    {
      const auto pairs = limited (objects[k].overlapping (), o);
      std::printf ("\n== %s = %d, %s, %s: %zu pairs\n", sweep.c_str (), value, method_name.c_str (), objects[k].label.c_str (), pairs.size ());
      const auto results = method (views[k], objects[k], pairs);
      const std::size_t c = countIf (results, [] (const PairResult& r) { return r.correct; });
      const std::size_t w = countIf (results, [] (const PairResult& r) { return r.wrong (); });
      for (const EvalView& v : views[k])
        descriptors.push_back (static_cast<double> (v.tensors->size ()));
      csv << sweep << ',' << value << ',' << method_name << ',' << objects[k].label << ',' << pairs.size () << ',' << c << ','
          << w << ',' << median (descriptors) << '\n';
      all.pairs += pairs.size ();
      all.correct += c;
      all.wrong += w;
    }
    csv << sweep << ',' << value << ',' << method_name << ",all," << all.pairs << ',' << all.correct << ',' << all.wrong << ','
        << median (descriptors) << '\n';
    return all;
  }

  std::string
  countsText (const PointCounts& c)
  {
    return fractionText (c.correct, c.pairs) + " (" + std::to_string (c.wrong) + " wrong)";
  }

  /** Figs. 15-16 (--resolution) and Fig. 20 (--spin): success on the overlapping pairs against faces per
    * view, and for the tensors also against tensors per view. */
  void
  runResolution (const std::vector<RealObject>& objects, bool tensors_sweep, bool spin, const Options& o)
  {
    std::ofstream csv (o.out + "/resolution.csv");
    csv << "sweep,value,method,object,pairs,correct,wrong,median_tensors_per_view\n";
    std::vector<SummaryRow> rows;
    const PairMethod tensor_method = [&] (const EvalViews& v, const RealObject& object, const std::vector<std::pair<int, int>>& pairs) {
      return runTensorPairs (v, object.dims, pairs, o.params);
    };
    // Paper, Fig. 16 (seven objects, before global verification) and Fig. 20 (three objects): tensors
    // ~50% at 100 faces, ~80% at 200 (84% in Fig. 20), 100% at 600; spin images 30% at 200, 61% at 600.
    const std::map<int, std::string> paper_tensor = {{100, "~50%"}, {200, "~80% (Fig. 20: 84%)"}, {400, "~90%"}, {600, "~90% (Fig. 20: 100%)"}, {1000, "-"}};
    const std::map<int, std::string> paper_spin = {{100, "-"}, {200, "30%"}, {400, "-"}, {600, "61%"}, {1000, "-"}};
    for (int faces : {100, 200, 400, 600, 1000})
    {
      pcl::registration::TensorRegistrationParams params = o.params;
      params.preparation.target_faces = faces;
      std::vector<EvalViews> views;
      for (const RealObject& object : objects)
      {
        views.push_back (object.views);
        prepareViews (views.back (), params);  // D comes from the fine meshes: it does not depend on the faces
      }
      const PairMethod at_faces = [&] (const EvalViews& v, const RealObject& object, const std::vector<std::pair<int, int>>& pairs) {
        return runTensorPairs (v, object.dims, pairs, params);
      };
      const PointCounts t = sweepPoint ("faces", faces, "tensor", at_faces, objects, views, o, csv);
      std::string spin_text;
      if (spin)
      {
        const PairMethod spin_method = [&] (const EvalViews& v, const RealObject& object, const std::vector<std::pair<int, int>>& pairs) {
          return runSpinImagePairs (v, object.dims, pairs, params, SpinImageParams ());
        };
        spin_text = countsText (sweepPoint ("faces", faces, "spin", spin_method, objects, views, o, csv));
      }
      rows.push_back ({spin ? "Figs. 16 and 20" : "Fig. 16", std::to_string (faces) + " faces per view: correct (wrong) on pairs with overlap >= 0.5",
                       paper_tensor.at (faces) + (spin ? " / spin images " + paper_spin.at (faces) : std::string ()),
                       countsText (t), "", spin_text});
    }
    const std::map<int, std::string> paper_tensors = {{100, "-"}, {300, "-"}, {500, "~90%"}, {700, "~90%"}};
    for (int count : tensors_sweep ? std::vector<int>{100, 300, 500, 700} : std::vector<int>{})
    {
      std::vector<EvalViews> views;
      for (const RealObject& object : objects)
      {
        views.push_back (object.views);
        subsampleTensors (views.back (), static_cast<std::size_t> (count), 2006);
      }
      const PointCounts t = sweepPoint ("tensors", count, "tensor", tensor_method, objects, views, o, csv);
      rows.push_back ({"Fig. 16", std::to_string (count) + " tensors per view (1000 faces): correct (wrong) on pairs with overlap >= 0.5",
                       paper_tensors.at (count), countsText (t), "", ""});
    }
    writeSummaryCsv (o.out + "/summary_resolution.csv", rows);
  }

  // ---------------------------------------------------------------- Fig. 21

  void
  runDiscrimination (const std::vector<RealObject>& objects, const Options& o)
  {
    // 700 descriptors per view need more reduced vertices than the pipeline's 1000 faces give.
    pcl::registration::TensorRegistrationParams params = o.params;
    params.preparation.target_faces = 2000;
    const DiscriminationParams d;
    std::ofstream csv (o.out + "/discrimination.csv");
    csv << "object,model,scene,descriptor,rank,error_bins\n";
    std::vector<double> tensor_all, spin_all;
    for (const RealObject& object : objects)
    {
      EvalViews views = object.views;
      prepareViews (views, params);
      for (const auto& [m, s] : limited (object.overlapping (), o))
      {
        const DiscriminationErrors e = measureDiscrimination (views[m], views[s], object.dims, params, d);
        for (std::size_t i = 0; i < e.tensor_bins.size (); ++i)
          csv << object.label << ',' << views[m].name << ',' << views[s].name << ",tensor," << i << ',' << e.tensor_bins[i] << '\n';
        for (std::size_t i = 0; i < e.spin_bins.size (); ++i)
          csv << object.label << ',' << views[m].name << ',' << views[s].name << ",spin," << i << ',' << e.spin_bins[i] << '\n';
        tensor_all.insert (tensor_all.end (), e.tensor_bins.begin (), e.tensor_bins.end ());
        spin_all.insert (spin_all.end (), e.spin_bins.begin (), e.spin_bins.end ());
        std::printf ("  %s %-9s <- %-9s tensor matches %zu (median error %.1f bins), spin matches %zu (median %.1f bins)\n",
                     object.label.c_str (), views[m].name.c_str (), views[s].name.c_str (), e.tensor_bins.size (),
                     median (e.tensor_bins), e.spin_bins.size (), median (e.spin_bins));
      }
    }
    const auto below = [] (const std::vector<double>& v, double bound) {
      return fractionText (static_cast<std::size_t> (std::count_if (v.begin (), v.end (), [&] (double x) { return x < bound; })), v.size ());
    };
    std::vector<SummaryRow> rows;
    rows.push_back ({"Fig. 21", "best matches with ground-truth displacement < 5 bins (paper: 2 cm ~ 5 mesh resolutions); tensors 15^3 / spin images 9x17 (width 8)",
                     "97.5% / 53.5%", below (tensor_all, 5.0), "", below (spin_all, 5.0)});
    rows.push_back ({"Fig. 21", "... < 2 bins", "-", below (tensor_all, 2.0), "", below (spin_all, 2.0)});
    rows.push_back ({"Fig. 21", "... median displacement (bins)", "-", numberText (median (tensor_all), 1), "", numberText (median (spin_all), 1)});
    writeSummaryCsv (o.out + "/summary_discrimination.csv", rows);
  }

  // ---------------------------------------------------------------- Fig. 13 and Section 7.5

  std::vector<PairResult>
  runSyntheticSet (const std::string& label, const pcl::ScanMesh& mesh, double noise, const Options& o)
  {
    pcl::SyntheticViewParams view_params;
    view_params.noise_sigma_resolutions = noise;
    std::printf ("\n== synthetic views of %s, noise sigma %g d_res\n", label.c_str (), noise);
    EvalViews views = makeSyntheticViews (mesh, view_params);
    const pcl::ObjectDimensions dims = prepareViews (views, o.params);
    printViews (views, dims);
    const auto pairs = limited (pcl::adjacentViewPairs (pcl::makeDefaultViewDirections (view_params.up)), o);
    return runTensorPairs (views, dims, pairs, o.params);
  }

  /** Fraction of the correct pairs whose \a error is below \a bound. */
  std::string
  belowText (const std::vector<PairResult>& results, double PairResult::*error, double bound)
  {
    const auto correct = countIf (results, [] (const PairResult& r) { return r.correct; });
    return fractionText (countIf (results, [&] (const PairResult& r) { return r.correct && r.*error < bound; }), correct);
  }

  void
  runAccuracy (const Options& o)
  {
    const std::vector<std::pair<std::string, std::string>> models = {
        {"bunny", o.data + "/stanford/bunny/bun_zipper.ply"}, {"dragon", o.data + "/stanford/dragon_recon/dragon_vrip_res3.ply"},
        {"example", ""}};
    std::vector<SummaryRow> rows;
    std::vector<std::vector<PairResult>> all;
    for (const auto& [label, path] : models)
    {
      const pcl::ScanMesh mesh = path.empty () ? pcl::makeExampleObject () : pcl::io::loadScanMesh (path);
      all.push_back (runSyntheticSet (label, mesh, 0.0, o));
      writePairCsv (o.out + "/accuracy_" + label + ".csv", all.back ());
    }
    for (std::size_t k = 0; k <= all.size (); ++k)
    {
      const auto results = k < all.size () ? all[k] : concat (all);
      const std::string label = k < all.size () ? models[k].first : "all three";
      const auto correct = [] (const PairResult& r) { return r.correct; };
      const auto nan = std::nan ("");
      std::vector<double> rot, trans;
      for (const PairResult& r : results)
      {
        rot.push_back (r.correct ? r.rotation_error_deg : nan);
        trans.push_back (r.correct ? r.translation_error_res : nan);
      }
      rows.push_back ({"Fig. 13", label + ": correct adjacent pairs (30 deg apart)", "all 26 views registered",
                       fractionText (countIf (results, correct), results.size ()), "", ""});
      rows.push_back ({"Fig. 13", label + ": rotation error < 0.1 deg (of the correct)", "most", belowText (results, &PairResult::rotation_error_deg, 0.1), "", ""});
      rows.push_back ({"Fig. 13", label + ": translation error (Eq. 12) < 0.1 d_res (of the correct)", "most",
                       belowText (results, &PairResult::translation_error_res, 0.1), "", ""});
      rows.push_back ({"Fig. 13", label + ": translation error at the scene centroid < 0.1 d_res (of the correct)", "-",
                       belowText (results, &PairResult::centroid_error_res, 0.1), "", ""});
      rows.push_back ({"Fig. 13", label + ": median rotation (deg) / translation (d_res) error", "< 0.1 / < 0.1",
                       numberText (median (rot), 4) + " / " + numberText (median (trans), 4), "", ""});
    }
    writeSummaryCsv (o.out + "/summary_accuracy.csv", rows);
  }

  void
  runNoise (const Options& o)
  {
    const pcl::ScanMesh mesh = pcl::io::loadScanMesh (o.data + "/stanford/bunny/bun_zipper.ply");
    std::ofstream csv (o.out + "/noise.csv");
    csv << "sigma_res,pairs,correct,wrong,correct_pct,median_rotation_error_deg,median_centroid_error_res\n";
    std::vector<SummaryRow> rows;
    for (int sigma : {0, 1, 2, 3, 4})
    {
      const auto results = runSyntheticSet ("bunny", mesh, sigma, o);
      writePairCsv (o.out + "/noise_sigma" + std::to_string (sigma) + ".csv", results);
      const std::size_t correct = countIf (results, [] (const PairResult& r) { return r.correct; });
      const std::size_t wrong = countIf (results, [] (const PairResult& r) { return r.wrong (); });
      std::vector<double> rot, centroid;
      for (const PairResult& r : results)
        if (r.correct)
        {
          rot.push_back (r.rotation_error_deg);
          centroid.push_back (r.centroid_error_res);
        }
      csv << sigma << ',' << results.size () << ',' << correct << ',' << wrong << ','
          << 100.0 * static_cast<double> (correct) / static_cast<double> (std::max<std::size_t> (results.size (), 1)) << ','
          << median (rot) << ',' << median (centroid) << '\n';
      rows.push_back ({"Sec. 7.5", "synthetic bunny adjacent pairs: correct (wrong) at sigma = " + std::to_string (sigma) + " d_res",
                       sigma == 0 ? "-" : sigma <= 3 ? "close to 100%" : "some pairs fail",
                       fractionText (correct, results.size ()) + " (" + std::to_string (wrong) + " wrong)", "", ""});
    }
    writeSummaryCsv (o.out + "/summary_noise.csv", rows);
  }

  /** Run one experiment and write run_<name>.csv: its mode and wall time, for doc/results.md. */
  void
  timed (const std::string& name, const Options& o, const std::function<void ()>& experiment)
  {
    const std::time_t start = std::time (nullptr);
    pcl::StopWatch watch;
    experiment ();
    char started[32];
    std::strftime (started, sizeof started, "%Y-%m-%dT%H:%MZ", std::gmtime (&start));
    std::ofstream csv (o.out + "/run_" + name + ".csv");
    csv << "experiment,mode,started_utc,wall_seconds\n"
        << name << ',' << (o.max_pairs == 0 ? std::string ("full") : std::to_string (o.max_pairs) + " pairs per object") << ',' << started << ',' << std::lround (watch.getTimeSeconds ()) << '\n';
    std::printf ("\n== %s: %.0f s\n", name.c_str (), watch.getTimeSeconds ());
  }

  int
  run (int argc, char** argv)
  {
    const Options o = parseOptions (argc, argv);
    const Selection s = parseSelection (argc, argv);
    std::filesystem::create_directories (o.out);
    pcl::StopWatch total;
    if (s.real ())
    {
      std::vector<RealObject> objects;
      timed ("loading", o, [&] { objects = loadRealObjects (o); });
      if (s.efficiency)
        timed ("efficiency", o, [&] { runEfficiency (objects, o); });
      if (s.overlap)
        timed ("overlap", o, [&] { runOverlap (objects, false, o); });
      if (s.baseline)
        timed ("baseline", o, [&] { runOverlap (objects, true, o); });
      if (s.stability)
        timed ("stability", o, [&] { runStability (objects, o); });
      if (s.resolution || s.spin)
        timed ("resolution", o, [&] { runResolution (objects, s.resolution, s.spin, o); });
      if (s.discrimination)
        timed ("discrimination", o, [&] { runDiscrimination (objects, o); });
    }
    if (s.accuracy)
      timed ("accuracy", o, [&] { runAccuracy (o); });
    if (s.noise)
      timed ("noise", o, [&] { runNoise (o); });
    std::printf ("\neval_paper: done in %.0f s\n", total.getTimeSeconds ());
    return 0;
  }
}

int
main (int argc, char** argv)
{
  return evalMain (argc, argv, "eval_paper", printHelp, run);
}
