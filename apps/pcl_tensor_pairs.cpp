/*
 * pcl_tensor_pairs: the per-pair work of a multiview run as a job of its own, on views that
 * pcl_tensor_prepare --tensors put in the cache: rank the pairs worth registering, or register a list
 * of pairs into a results file that pcl_tensor_model --pairs-results reads (scripts/pcl_tensor_dask.py
 * runs such jobs on many machines).
 */
#include "cached_views.h"
#include "multiview_options.h"

#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/console/time.h>
#include <pcl/io/atomic_file.h>
#include <pcl/io/registration_report_json.h>
#include <pcl/io/view_pair_results.h>
#include <pcl/io/view_pairs_io.h>
#include <pcl/registration/multiview_tensor_registration.h>

#include <filesystem>
#include <iostream>

using namespace pcl::console;

namespace
{
  constexpr const char* kRemedy = "run pcl_tensor_prepare --tensors first, on all the views and with the same options";

  void
  printHelp (const char* name)
  {
    const pcl::registration::MultiviewRegistrationParams m;
    print_info ("The pair work of pcl_tensor_model as a job of its own, on views already in a cache (pcl_tensor_prepare\n"
                "--tensors, with the same views and options): rank the pairs, or register some of them.\n\n");
    print_info ("Usage: %s VIEW.{ply,pcd}... --cache DIR (--rank K | --pairs FILE) [-o FILE] [--json] [options]\n\n", name);
    print_info ("  --cache DIR        the cache folder pcl_tensor_prepare --tensors filled; required\n");
    print_info ("  --rank K           rank every pair by its tensors (as pcl_tensor_model does) and write a pairs file\n"
                "                     (\"A B\" per line) of each view's K best partners, best first\n");
    print_info ("  --pairs FILE       register each pair of FILE (\"A B\": file names or 0-based indices; B into A's frame),\n"
                "                     fully, as pcl_tensor_model does, and write a results file: one JSON object per line\n"
                "                     (model_file, model_id, scene_file, scene_id, report) for pcl_tensor_model --pairs-results\n");
    print_info ("  -o FILE            where to write the pairs or results, replaced whole (default: stdout)\n");
    print_info ("  --dims X,Y,Z       the object's dimensions D when known (default: from all views given, Eq. 1)\n");
    print_info ("  --dims-tolerance T how far registered views may exceed D after ICP, in d_res (default %g)\n",
                m.pairwise.verification.fine_dimension_tolerance);
    print_info ("  --faces N          faces per reduced mesh (default %d)\n", m.pairwise.preparation.target_faces);
    pcl_tensor_tools::printRankSampleHelp (m);
    print_info ("  --viewpoint x,y,z  perspective sensor at x,y,z looking at each scan (default: a PCD's pose; the pushbroom a PLY grid fits; else +z)\n");
    print_info ("  -j N               threads (default 0: every core); the output is the same for any number\n");
    print_info ("  --json             print a JSON summary (needs -o: stdout holds it)\n");
    print_info ("Give every view of the object, in the same order, to each job: D comes from all of them.\n");
    print_info ("Exit codes: 0 written (pairs that do not register are results too); 2 bad input or usage, or a view\n"
                "whose meshes or tensors are not valid in the cache.\n");
  }

  struct PairsOptions
  {
    std::vector<std::string> views;
    std::string cache, pairs, output;
    /** --rank K, or 0 with --pairs. */
    int rank = 0;
    bool json = false;
    unsigned threads = 0;
    pcl::registration::MultiviewRegistrationParams params;
  };

  PairsOptions
  parseOptions (int argc, char** argv)
  {
    PairsOptions o;
    parse_argument (argc, argv, "--cache", o.cache);
    if (o.cache.empty ())
      PCL_TENSOR_THROW (pcl::BadArgumentException, "--cache DIR is required; see --help");
    if (!std::filesystem::is_directory (o.cache))
      PCL_TENSOR_THROW (pcl::IOException, "no cache folder '" << o.cache << "': " << kRemedy);
    const bool rank = parse_argument (argc, argv, "--rank", o.rank) >= 0;
    parse_argument (argc, argv, "--pairs", o.pairs);
    if (rank == !o.pairs.empty ())
      PCL_TENSOR_THROW (pcl::BadArgumentException, "give either --rank K or --pairs FILE; see --help");
    if (rank && o.rank < 1)
      PCL_TENSOR_THROW (pcl::BadArgumentException, "--rank takes a number of partners per view (1 or more), got " << o.rank);
    parse_argument (argc, argv, "-o", o.output);
    o.json = find_switch (argc, argv, "--json");
    if (o.json && o.output.empty ())
      PCL_TENSOR_THROW (pcl::BadArgumentException, "--json prints a summary on stdout: give -o FILE for the output");
    if (!o.output.empty ())
      pcl_tensor_tools::requireWritableFolder (o.output);
    o.views = pcl_tensor_tools::scanFileArguments (argc, argv, {o.cache, o.pairs, o.output});
    if (o.views.size () < 2)
      PCL_TENSOR_THROW (pcl::BadArgumentException, "expected at least two VIEW files (.ply or .pcd); see --help");
    o.threads = pcl_tensor_tools::parseJobThreads (argc, argv);
    pcl_tensor_tools::parseMultiviewPairOptions (argc, argv, o.params);
    pcl::registration::checkParams (o.params);
    return o;
  }

  /** D as pcl_tensor_prepare --tensors and pcl_tensor_model take it: --dims, else Eq. 1 over all views. */
  pcl::ObjectDimensions
  objectDimensions (const PairsOptions& o, const std::vector<pcl_tensor_tools::CachedViewFile>& files)
  {
    const pcl::ObjectDimensions given = pcl::givenObjectDimensions (o.params.object_dimensions);
    return given.isSet () ? given : pcl_tensor_tools::dimensionsOfViews (files);
  }

  /** A view's meshes and its tensors for \a dims, both from the cache. */
  pcl::registration::TensorView::ConstPtr
  loadCachedView (const pcl::io::TensorViewCache& cache, const pcl_tensor_tools::CachedViewFile& file,
                  const pcl::ObjectDimensions& dims, const pcl::registration::TensorRegistrationParams& params)
  {
    auto view = std::make_shared<pcl::registration::TensorView> ();
    pcl_tensor_tools::requireValidEntry (cache.loadView (file.id, file.key, *view), file.file, "meshes", cache, kRemedy);
    pcl::PointCloud<pcl::TensorDescriptor>::Ptr tensors;
    const auto state = cache.loadTensors (file.id, file.key, dims, pcl::io::hashTensorParameters (params), tensors);
    pcl_tensor_tools::requireValidEntry (state, file.file, "tensors (for this D and settings)", cache, kRemedy);
    view->tensors = tensors;
    view->dimensions = dims;
    return view;
  }

  /** The views with their tensors (null: not needed), and the D of those tensors. */
  struct LoadedViews
  {
    std::vector<pcl::registration::TensorView::ConstPtr> views;
    pcl::ObjectDimensions dims;
    /** Each view's entry name and key, for what the cache keeps per pair. */
    std::vector<pcl::io::CachedViewReport> entries;
  };

  /** From the cache: every listed view's key and extents (for D), and the meshes and tensors of the
    * views in \a needed (all when empty). */
  LoadedViews
  loadViews (const PairsOptions& o, const std::vector<std::pair<int, int>>& needed, int argc, char** argv)
  {
    const pcl::io::TensorViewCache cache (o.cache);
    const std::size_t n = o.views.size ();
    std::vector<pcl_tensor_tools::CachedViewFile> files (n);
    pcl_tensor_tools::forEachJob (n, o.threads, [&] (std::size_t i) {
      files[i] = pcl_tensor_tools::readCachedExtents (cache, o.views[i], o.params.pairwise.preparation, argc, argv, kRemedy);
    });
    LoadedViews loaded;
    loaded.dims = objectDimensions (o, files);
    for (const auto& f : files)
    {
      loaded.entries.emplace_back ();
      loaded.entries.back ().id = f.id;
      loaded.entries.back ().key = f.key;
    }
    std::vector<char> used (n, needed.empty ());
    for (const auto& [a, b] : needed)
      used[a] = used[b] = 1;
    loaded.views.resize (n);
    pcl_tensor_tools::forEachJob (n, o.threads, [&] (std::size_t i) {
      if (used[i])
        loaded.views[i] = loadCachedView (cache, files[i], loaded.dims, o.params.pairwise);
    });
    return loaded;
  }

  /** Each view's \a k best partners, in rank order: the candidates among the first \a k of either view. */
  std::vector<pcl::registration::ViewPairCandidate>
  bestPartners (const std::vector<pcl::registration::ViewPairCandidate>& ranked, int k, std::size_t views)
  {
    std::vector<int> seen (views, 0);
    std::vector<pcl::registration::ViewPairCandidate> kept;
    for (const auto& c : ranked)
    {
      const bool first_wants = ++seen[c.first] <= k;
      const bool second_wants = ++seen[c.second] <= k;
      if (first_wants || second_wants)
        kept.push_back (c);
    }
    return kept;
  }

  /** The pairs file pcl_tensor_pairs --pairs and pcl_tensor_model --pairs read. */
  std::string
  formatPairs (const std::vector<pcl::registration::ViewPairCandidate>& pairs, const PairsOptions& o)
  {
    std::string text = "# pcl_tensor_pairs --rank " + std::to_string (o.rank) + ": each view's best partners, best first\n";
    for (const auto& p : pairs)
    {
      for (const int v : {p.first, p.second})
        if (o.views[v].find_first_of (" \t") != std::string::npos)
          PCL_TENSOR_THROW (pcl::BadArgumentException, "'" << o.views[v] << "': a pairs file line cannot hold white space "
                            "in a file name; rename it");
      text += o.views[p.first] + " " + o.views[p.second] + "\n";
    }
    return text;
  }

  /** -o, replaced whole, or stdout. */
  void
  writeOutput (const PairsOptions& o, const std::string& text)
  {
    if (o.output.empty ())
      std::cout << text << std::flush;
    else
      pcl::io::writeFileAtomically (o.output, text);
  }

  struct StageTimes
  {
    double load_ms = 0.0, work_ms = 0.0, write_ms = 0.0;
  };

  pcl::io::JsonReport
  jsonSummary (const PairsOptions& o, const LoadedViews& loaded, const StageTimes& t)
  {
    const Eigen::Vector3d& d = loaded.dims.D;
    pcl::io::JsonReport j;
    j["views"] = o.views.size ();
    j["dimensions"] = {d[0], d[1], d[2]};
    j["output"] = o.output;
    j["timings_ms"] = {{"load", t.load_ms}, {o.rank > 0 ? "ranking" : "registration", t.work_ms}, {"write", t.write_ms},
                       {"total", t.load_ms + t.work_ms + t.write_ms}};
    return j;
  }

  int
  rankPairs (const PairsOptions& o, int argc, char** argv)
  {
    StageTimes t;
    TicToc timer;
    timer.tic ();
    const LoadedViews loaded = loadViews (o, {}, argc, argv);
    t.load_ms = timer.toc ();
    timer.tic ();
    // Scores kept in the cache by earlier rankings of these views (or pcl_tensor_model's) are not computed again.
    const pcl::io::TensorViewCache cache (o.cache);
    const auto known = pcl::io::cachedPairScores (cache, loaded.entries) (loaded.dims, o.params.pairwise, o.params.ranking);
    const auto ranked = pcl::registration::ViewPairRanking (loaded.views, o.params.pairwise, o.params.ranking).rank ({}, o.threads, known);
    const auto kept = bestPartners (ranked, o.rank, o.views.size ());
    t.work_ms = timer.toc ();
    timer.tic ();
    writeOutput (o, formatPairs (kept, o));
    t.write_ms = timer.toc ();
    if (o.json)
    {
      pcl::io::JsonReport j = jsonSummary (o, loaded, t);
      j["candidates"] = ranked.size ();
      pcl::io::JsonReport pairs = pcl::io::JsonReport::array ();
      for (const auto& p : kept)
        pairs.push_back ({{"model", o.views[p.first]}, {"scene", o.views[p.second]}, {"score", p.score}});
      j["pairs"] = std::move (pairs);
      std::cout << pcl::io::dumpJson (j) << std::endl;
    }
    else if (!o.output.empty ())
    {
      print_info ("Ranked "); print_value ("%zu", ranked.size ()); print_info (" pairs of "); print_value ("%zu", o.views.size ());
      print_info (" views; "); print_value ("%zu", kept.size ()); print_info (" written to "); print_value ("%s", o.output.c_str ());
      print_info ("\nTimes (ms): load %.0f, ranking %.0f, write %.0f\n", t.load_ms, t.work_ms, t.write_ms);
    }
    return 0;
  }

  int
  registerPairs (const PairsOptions& o, int argc, char** argv)
  {
    const auto pairs = pcl::io::loadViewPairs (o.pairs, o.views);
    StageTimes t;
    TicToc timer;
    timer.tic ();
    const LoadedViews loaded = loadViews (o, pairs, argc, argv);
    t.load_ms = timer.toc ();
    timer.tic ();
    std::vector<pcl::io::ViewPairResult> results (pairs.size ());
    pcl_tensor_tools::forEachJob (pairs.size (), o.threads, [&] (std::size_t k) {
      const auto [a, b] = pairs[k];
      results[k] = pcl::io::makeViewPairResult (o.views[a], o.views[b], pcl::registration::registerTensorViews (
          loaded.views[a], loaded.views[b], loaded.dims, o.params.pairwise));
    });
    t.work_ms = timer.toc ();
    timer.tic ();
    writeOutput (o, pcl::io::formatViewPairResults (results));
    t.write_ms = timer.toc ();
    std::size_t registered = 0;
    for (const auto& r : results)
      registered += r.report.registered;
    if (o.json)
    {
      pcl::io::JsonReport j = jsonSummary (o, loaded, t);
      j["registered"] = registered;
      pcl::io::JsonReport list = pcl::io::JsonReport::array ();
      for (const auto& r : results)
        list.push_back ({{"model", r.model_file}, {"scene", r.scene_file}, {"registered", r.report.registered},
                         {"ambiguous", r.report.ambiguous}, {"hypotheses_tried", r.report.hypotheses_tried},
                         {"ms", r.report.timings.total_ms}});
      j["pairs"] = std::move (list);
      std::cout << pcl::io::dumpJson (j) << std::endl;
    }
    else if (!o.output.empty ())
    {
      print_info ("Registered "); print_value ("%zu", registered); print_info (" of "); print_value ("%zu", pairs.size ());
      print_info (" pairs; results written to "); print_value ("%s", o.output.c_str ());
      print_info ("\nTimes (ms): load %.0f, registration %.0f, write %.0f\n", t.load_ms, t.work_ms, t.write_ms);
    }
    return 0;
  }

  int
  run (int argc, char** argv)
  {
    const PairsOptions o = parseOptions (argc, argv);
    if (o.json)
      setVerbosityLevel (L_ALWAYS);
    return o.rank > 0 ? rankPairs (o, argc, argv) : registerPairs (o, argc, argv);
  }
}

int
main (int argc, char** argv)
{
  return pcl_tensor_tools::toolMain ("pcl_tensor_pairs", argc, argv, printHelp, run);
}
