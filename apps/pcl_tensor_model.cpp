/*
 * pcl_tensor_model: range images in, one 3D model out (Mian et al., 2006, Section 5 and Fig. 9):
 * every view registered automatically, global verification and registration, then volumetric
 * integration and marching cubes.
 */
#include "multiview_options.h"
#include "progress_bar.h"
#include "tool_main.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/console/time.h>
#include <pcl/io/atomic_file.h>
#include <pcl/io/cached_tensor_view.h>
#include <pcl/io/integration_volume_cache.h>
#include <pcl/io/model_run_record.h>
#include <pcl/io/scan_mesh_io.h>
#include <pcl/io/recorded_pair_registration.h>
#include <pcl/io/range_scan_io.h>
#include <pcl/io/scan_sensor_cache.h>
#include <pcl/io/registration_report_json.h>
#include <pcl/io/stanford_conf.h>
#include <pcl/io/view_pairs_io.h>
#include <pcl/registration/multiview_tensor_registration.h>
#include <pcl/surface/scan_volumetric_integration.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

using namespace pcl::console;

namespace
{
  constexpr int kExitModelled = 0;

  void
  printHelp (const char* name)
  {
    const pcl::registration::MultiviewRegistrationParams m;
    const pcl::VolumetricIntegrationParams v;
    print_info ("Build a 3D model from range images, registered automatically with tensors\n"
                "(Mian, Bennamoun & Owens, IJCV 2006), then integrated volumetrically (Curless & Levoy, 1996).\n\n");
    print_info ("Usage: %s VIEW.{ply,pcd}... -o model.ply [--conf poses.conf] [--pairs FILE] [--loop]\n"
                "       [--voxel SIZE] [--json] [options]\n\n", name);
    print_info ("Views come in any order: every pair is ranked by its tensors and the best are registered until\n"
                "the views are joined; views no verified pair joins to the rest make a model of their own.\n");
    print_info ("  -o FILE            the model (binary PLY mesh with normals); required\n");
    print_info ("  --conf FILE        the estimated poses, Stanford .conf style (default: the model's name with .conf)\n");
    print_info ("  --pairs FILE       overlapping pairs, one \"A B\" per line (file names or 0-based indices)\n");
    print_info ("  --cache DIR        keep each view's meshes and tensors in DIR (pcl_tensor_prepare's cache): a re-run,\n"
                "                     or one with views added, computes only what is new\n");
    print_info ("  --keep-poses CONF  views that CONF names keep its poses, and only the others are registered, to them\n"
                "                     and moved by the global step: to add views to a model made before, give its .conf\n"
                "                     (with --cache, the old views' voxels come from it too: only the new are integrated)\n");
    print_info ("  --pairs-results F  pair registrations computed elsewhere (pcl_tensor_pairs; repeat for several\n"
                "                     files): pairs are taken from them, never registered here\n");
    print_info ("  --loop             a turntable: the last view overlaps the first (closes the loop)\n");
    print_info ("  --ordered          the paper's order instead (Fig. 9): each view overlaps one given before it\n");
    print_info ("  --references N     with --ordered: registered views each new view is tried against, newest first,\n"
                "                     0 = all (default %d)\n", m.max_references);
    print_info ("  --no-global        skip the global registration step\n");
    print_info ("  --dims X,Y,Z       the object's dimensions D when known (default: from all views, Eq. 1)\n");
    print_info ("  --dims-tolerance T how far registered views may exceed D, in d_res, after ICP (local, default %g)\n"
                "                     and over all views (global, Section 4.2, default %g); raise it when D comes\n"
                "                     from views that never see an extent whole\n",
                m.pairwise.verification.fine_dimension_tolerance, m.global_verification.tolerance);
    print_info ("  --voxel SIZE       voxel edge in the scans' units (default: %g d_res)\n", v.voxel_size_resolutions);
    print_info ("  --voxel-res K      voxel edge in d_res, when --voxel is not given (default %g)\n", v.voxel_size_resolutions);
    print_info ("  --max-memory MB    refuse a voxel volume larger than this (default %zu)\n", v.max_memory_bytes >> 20);
    print_info ("  --faces N          faces per reduced mesh (default %d)\n", m.pairwise.preparation.target_faces);
    pcl_tensor_tools::printRankSampleHelp (m);
    print_info ("  --viewpoint x,y,z  perspective sensor at x,y,z looking at each scan (default: a PCD's pose; the pushbroom a PLY grid fits; else +z)\n");
    print_info ("  -j N               threads (default 0: every core); the result is the same for any number\n");
    print_info ("  --json             print a JSON summary instead of text\n");
    print_info ("Outputs: one model and .conf per group of views registered together: the largest to -o and --conf,\n"
                "the others beside them as NAME_part2.ply, NAME_part2.conf, ...\n");
    print_info ("Exit codes: 0 every view registered into one model; 3 some views could not be registered or the\n"
                "views form several models (each written; the views left out are named on stderr); 2 bad input or usage.\n");
  }

  struct ModelOptions
  {
    std::vector<std::string> views;
    std::string output, conf, pairs, cache, keep_poses;
    std::vector<std::string> pairs_results;
    bool json = false;
    unsigned threads = 0;
    pcl::registration::MultiviewRegistrationParams registration;
    pcl::VolumetricIntegrationParams integration;
  };

  std::string
  baseName (const std::string& path)
  {
    const auto slash = path.find_last_of ("/\\");
    return slash == std::string::npos ? path : path.substr (slash + 1);
  }

  ModelOptions
  parseOptions (int argc, char** argv)
  {
    ModelOptions o;
    parse_argument (argc, argv, "-o", o.output);
    if (o.output.empty ())
      PCL_TENSOR_THROW (pcl::BadArgumentException, "-o model.ply is required; see --help");
    o.conf = o.output.substr (0, o.output.find_last_of ('.')) + ".conf";
    parse_argument (argc, argv, "--conf", o.conf);
    pcl_tensor_tools::requireWritableFolder (o.output);
    pcl_tensor_tools::requireWritableFolder (o.conf);
    parse_argument (argc, argv, "--pairs", o.pairs);
    parse_argument (argc, argv, "--cache", o.cache);
    parse_argument (argc, argv, "--keep-poses", o.keep_poses);
    for (int i = 1; i + 1 < argc; ++i)
      if (std::string (argv[i]) == "--pairs-results")
        o.pairs_results.push_back (argv[++i]);
    o.views = pcl_tensor_tools::scanFileArguments (argc, argv, {o.output, o.conf});
    if (o.views.size () < 2)
      PCL_TENSOR_THROW (pcl::BadArgumentException, "expected at least two VIEW files (.ply or .pcd); see --help");
    for (const auto& view : o.views)
      if (!pcl::io::isStanfordConfFileName (baseName (view)))
        PCL_TENSOR_THROW (pcl::BadArgumentException, "'" << view << "': a .conf line names each view, and cannot hold "
                          "white space in a file name; rename it");
    o.json = find_switch (argc, argv, "--json");
    o.threads = pcl_tensor_tools::parseThreads (argc, argv);
    o.registration.loop = find_switch (argc, argv, "--loop");
    if (find_switch (argc, argv, "--ordered"))
      o.registration.search = pcl::registration::ViewSearch::ORDERED;
    o.registration.global_registration = !find_switch (argc, argv, "--no-global");
    parse_argument (argc, argv, "--references", o.registration.max_references);
    pcl_tensor_tools::parseMultiviewPairOptions (argc, argv, o.registration);
    double voxel = 0.0;
    if (parse_argument (argc, argv, "--voxel", voxel) >= 0 && !(voxel > 0.0))
      PCL_TENSOR_THROW (pcl::BadArgumentException, "--voxel must be positive, got " << voxel);
    o.integration.voxel_size = voxel;
    parse_argument (argc, argv, "--voxel-res", o.integration.voxel_size_resolutions);
    unsigned int megabytes = 0;
    if (parse_argument (argc, argv, "--max-memory", megabytes) >= 0)
      o.integration.max_memory_bytes = std::size_t (megabytes) << 20;
    return o;
  }

  /** How the tools choose a scan's sensor besides its file: the --viewpoint option as given (empty without it). */
  std::string
  sensorChoice (int argc, char** argv)
  {
    std::string how;
    parse_argument (argc, argv, "--viewpoint", how);
    return how;
  }

  /** View \a i of the command line: its file, cloud and sensor (--viewpoint or from the file); with a
    * cache, the sensor is kept there, so that a later run needs not read the scan (sensorLookup()). */
  pcl::io::MultiviewInputLoader
  viewLoader (const std::vector<std::string>& files, int argc, char** argv, const pcl::io::TensorViewCache* cache)
  {
    return [&files, argc, argv, cache] (std::size_t i) {
      const pcl::io::RangeScan scan = pcl_tensor_tools::loadScan (files[i], argc, argv);
      pcl::registration::MultiviewInput view;
      view.name = files[i];
      view.viewpoint = scan.viewpoint;
      view.cloud = scan.cloud;
      if (cache)
        pcl::io::saveScanSensor (*cache, pcl::io::viewIdOf (files[i]),
                                 pcl::io::scanSensorKey (pcl::io::hashFileContents (files[i]), sensorChoice (argc, argv)),
                                 scan.viewpoint);
      return view;
    };
  }

  /** View \a i's file and the sensor an earlier run read it with, from the cache. */
  pcl::io::MultiviewInputLookup
  sensorLookup (const std::vector<std::string>& files, int argc, char** argv, const pcl::io::TensorViewCache& cache)
  {
    return [&files, &cache, how = sensorChoice (argc, argv)] (std::size_t i, pcl::registration::MultiviewInput& view) {
      view.name = files[i];
      return pcl::io::loadScanSensor (cache, pcl::io::viewIdOf (files[i]),
                                      pcl::io::scanSensorKey (pcl::io::hashFileContents (files[i]), how), view.viewpoint);
    };
  }

  /** The pose of each view that the --keep-poses file names (none without it), read before any view. */
  struct KeptPoses
  {
    std::vector<pcl::io::StanfordConfEntry> entries;
    std::vector<int> entry_of_view;  ///< -1: not named

    KeptPoses (const std::string& conf, const std::vector<std::string>& views)
      : entries (conf.empty () ? std::vector<pcl::io::StanfordConfEntry> () : pcl::io::loadStanfordConf (conf)),
        entry_of_view (pcl::io::confEntriesOfFiles (entries, views))
    {
      if (!conf.empty () && std::count (entry_of_view.begin (), entry_of_view.end (), -1) == static_cast<long> (views.size ()))
        print_warn ("--keep-poses %s names none of the views: every view is registered\n", conf.c_str ());
    }

    /** The .conf entry of view \a i, registered: a kept pose as it was read (so that it stays the same,
      * to the last digit, however often a model is extended), another as fromPose() writes it. */
    pcl::io::StanfordConfEntry
    entryOf (const pcl::registration::MultiviewRegistrationResult& result, std::size_t i) const
    {
      const auto& v = result.views[i];
      if (!v.pose_kept || entry_of_view[i] < 0)
        return pcl::io::StanfordConfEntry::fromPose (baseName (v.name), v.pose);
      pcl::io::StanfordConfEntry kept = entries[entry_of_view[i]];
      kept.file = baseName (v.name);
      return kept;
    }

    void
    applyTo (std::vector<pcl::registration::MultiviewInput>& inputs) const
    {
      for (std::size_t i = 0; i < inputs.size (); ++i)
        if (entry_of_view[i] >= 0)
        {
          inputs[i].pose_known = true;
          inputs[i].known_pose = entries[entry_of_view[i]].pose ();
        }
    }
  };

  void
  saveConf (const std::string& path, const pcl::registration::MultiviewRegistrationResult& result, int component,
            const KeptPoses& kept)
  {
    std::vector<pcl::io::StanfordConfEntry> entries;
    for (std::size_t i = 0; i < result.views.size (); ++i)
      if (result.views[i].registered && result.views[i].component == component)
        entries.push_back (kept.entryOf (result, i));
    pcl::io::AtomicFileWriter file (path);
    pcl::io::saveStanfordConf (file.temporaryPath (), entries);
    file.commit ();
  }

  /** What was built from one component. */
  struct ComponentModel
  {
    std::string model, conf;
    std::size_t views = 0;
    pcl::ScanMesh mesh;
    pcl::VolumetricIntegrationReport volume;
  };

  /** Where component \a c goes: -o and --conf for the first, NAME_partN beside them for the others. */
  std::string
  partPath (const std::string& path, int c)
  {
    if (c == 0)
      return path;
    const std::filesystem::path p (path);
    return (p.parent_path () / (p.stem ().string () + "_part" + std::to_string (c + 1) + p.extension ().string ())).string ();
  }

  struct StageTimes
  {
    double preparation_ms = 0.0, integration_ms = 0.0, write_ms = 0.0, total_ms = 0.0;
  };

  pcl::io::JsonReport
  toJson (const ComponentModel& m)
  {
    return {{"model", m.model}, {"conf", m.conf}, {"views", m.views}, {"volume", pcl::io::toJson (m.volume)},
            {"mesh", {{"vertices", m.mesh.cloud->size ()}, {"triangles", m.mesh.polygons.size ()}}}};
  }

  std::string
  jsonSummary (const pcl::registration::MultiviewRegistrationResult& r, const std::vector<ComponentModel>& models,
               const StageTimes& t)
  {
    pcl::io::JsonReport j;
    if (!models.empty ())
      j = toJson (models.front ());
    j.update (pcl::io::toJson (r));
    pcl::io::JsonReport all = pcl::io::JsonReport::array ();
    for (const auto& m : models)
      all.push_back (toJson (m));
    j["models"] = std::move (all);
    auto& timings = j["timings_ms"];
    timings["preparation"] = t.preparation_ms;
    timings["integration"] = t.integration_ms;
    timings["write"] = t.write_ms;
    timings["total"] = t.total_ms;
    return pcl::io::dumpJson (j);
  }

  void
  printText (const pcl::registration::MultiviewRegistrationResult& r, const std::vector<ComponentModel>& models,
             const StageTimes& t)
  {
    print_info ("Registered "); print_value ("%zu", r.registeredCount ()); print_info (" of ");
    print_value ("%zu", r.views.size ()); print_info (" views");
    for (const auto& m : models)
    {
      print_info ("; a model of "); print_value ("%zu", m.views); print_info (" views, ");
      print_value ("%zu", m.mesh.polygons.size ()); print_info (" triangles, written to "); print_value ("%s", m.model.c_str ());
      print_info (", poses to "); print_value ("%s", m.conf.c_str ());
    }
    print_info ("\n");
    print_info ("Times (ms): preparation (loading, meshing, tensors) %.0f, ranking %.0f, pairwise %.0f (%zu pairs), global %.0f, "
                "integration %.0f, write %.0f, total %.0f\n", t.preparation_ms + r.timings.prepare_ms + r.timings.tensors_ms,
                r.timings.ranking_ms, r.timings.pairwise_ms, r.attempts.size (), r.timings.global_ms, t.integration_ms,
                t.write_ms, t.total_ms);
  }

  /** One line per view that is not in the main model, saying why or where it went (for stderr). */
  std::string
  viewsLeftOut (const pcl::registration::MultiviewRegistrationResult& r, const std::vector<ComponentModel>& models)
  {
    std::ostringstream lines;
    for (const auto& v : r.views)
      if (!v.registered)
        lines << "pcl_tensor_model: not registered: " << v.name << ": "
              << (v.error.empty () ? "no pair with it passed local and global verification" : v.error) << "\n";
      else if (v.component > 0)
        lines << "pcl_tensor_model: in a separate model: " << v.name << ": " << models[v.component].model << "\n";
    return lines.str ();
  }

  /** The files a run reads besides its settings: the views, and any pairs or pair results. */
  std::vector<std::string>
  inputFiles (const ModelOptions& o)
  {
    std::vector<std::string> files = o.views;
    files.insert (files.end (), o.pairs_results.begin (), o.pairs_results.end ());
    for (const auto& file : {o.pairs, o.keep_poses})
      if (!file.empty ())
        files.push_back (file);
    return files;
  }

  /** What changes a run's outputs besides its input files: every argument but -j and --json. */
  std::vector<std::string>
  outputSettings (int argc, char** argv)
  {
    std::vector<std::string> settings;
    for (int i = 1; i < argc; ++i)
    {
      const std::string a = argv[i];
      if (a == "-j" && i + 1 < argc)
        ++i;
      else if (a != "--json")
        settings.push_back (a);
    }
    return settings;
  }

  /** A run whose inputs, settings and outputs are those of the run recorded in the cache: nothing
    * is computed, what it reported is reported again. */
  int
  replay (const pcl::io::ModelRunRecord& record, const ModelOptions& o)
  {
    if (o.json)
      std::cout << record.report << std::endl;
    else
    {
      print_info ("Nothing new since the last run with this cache: its outputs are in place (");
      for (const auto& out : record.outputs)
        print_value ("%s ", out.first.c_str ());
      print_info (")\n");
    }
    std::cerr << record.messages;
    return record.exit_code;
  }

  /** The cache key of the voxels of component \a c: of its views of kept poses, as an earlier run
    * stored them, or of all its views, as this run stores them; each with its pose as its .conf line
    * gives it back. */
  pcl::io::TensorViewCacheKey
  volumeKey (const pcl::registration::MultiviewRegistrationResult& result, const std::vector<pcl::io::CachedViewReport>& prepared,
             int c, bool kept_only, const KeptPoses& kept, const pcl::VolumetricIntegrationParams& params)
  {
    std::vector<pcl::io::TensorViewCacheKey> keys;
    pcl::registration::ViewPoses poses;
    for (std::size_t i = 0; i < result.views.size (); ++i)
    {
      const auto& v = result.views[i];
      if (v.registered && v.component == c && (!kept_only || v.pose_kept))
      {
        keys.push_back (prepared[i].key);
        poses.push_back (kept.entryOf (result, i).pose ());
      }
    }
    return pcl::io::integrationVolumeKey (keys, poses, params);
  }

  /** Volumetric integration of component \a c into its own model. With a cache, the voxels of its views
    * of kept poses are taken from it when an earlier run stored them (only the other views are
    * integrated), and the main model's voxels are stored for the next run that extends it. */
  ComponentModel
  integrateComponent (const pcl::registration::MultiviewRegistrationResult& result, const ModelOptions& o, int c,
                      const pcl::io::TensorViewCache* cache, const std::vector<pcl::io::CachedViewReport>& prepared,
                      const KeptPoses& kept_poses)
  {
    ComponentModel m;
    m.model = partPath (o.output, c);
    m.conf = partPath (o.conf, c);
    pcl::ScanVolumetricIntegration integration;
    integration.setParams (o.integration);
    integration.setNumberOfThreads (o.threads);
    const bool any_kept = std::any_of (result.views.begin (), result.views.end (),
                                       [c] (const auto& v) { return v.registered && v.component == c && v.pose_kept; });
    if (cache && any_kept)
      integration.setInitialVolume (pcl::io::loadIntegrationVolume (*cache, pcl::io::integrationVolumeId (o.keep_poses),
                                                                    volumeKey (result, prepared, c, true, kept_poses, o.integration)));
    integration.setKeepVolume (cache && c == 0);
    integration.setInputViews (pcl::registration::registeredIntegrationViews (result, c, !integration.getInitialVolume ()));
    integration.reconstruct (m.mesh);
    m.volume = integration.getReport ();
    m.views = m.volume.views;
    if (integration.getVolume ())
      pcl::io::saveIntegrationVolume (*cache, pcl::io::integrationVolumeId (m.conf),
                                      volumeKey (result, prepared, c, false, kept_poses, o.integration), *integration.getVolume ());
    return m;
  }

  int
  run (int argc, char** argv)
  {
    const ModelOptions o = parseOptions (argc, argv);
    if (o.json)
      setVerbosityLevel (L_ALWAYS);
    TicToc total, timer;
    total.tic ();
    StageTimes t;
    pcl_tensor_tools::ProgressBar progress;

    // Parameters are checked before any view is read.
    pcl::registration::MultiviewTensorRegistration registration;
    registration.setParams (o.registration);
    registration.setNumberOfThreads (o.threads);
    pcl::ScanVolumetricIntegration integration;
    integration.setParams (o.integration);
    timer.tic ();
    // Each view loaded, meshed and its tensors computed in one pass (or taken from the cache), so that
    // the raw scans are not all in memory at once.
    std::unique_ptr<pcl::io::TensorViewCache> cache;
    pcl::io::TensorViewCacheKey run_key;
    if (!o.cache.empty ())
    {
      cache = std::make_unique<pcl::io::TensorViewCache> (o.cache);
      std::vector<std::string> settings = outputSettings (argc, argv);
      // The library's own settings too: a run recorded before its defaults changed is made again.
      settings.push_back ("library " + std::to_string (pcl::io::hashModelRunSettings (o.registration, o.integration)));
      run_key = pcl::io::modelRunKey (inputFiles (o), settings);
      pcl::io::ModelRunRecord record;
      if (pcl::io::loadModelRun (*cache, run_key, record))
        return replay (record, o);
    }
    const KeptPoses kept (o.keep_poses, o.views);
    std::vector<pcl::registration::MultiviewInput> inputs;
    const pcl::registration::MultiviewProgress show = [&progress] (pcl::registration::MultiviewStage stage, std::size_t done,
                                                                   std::size_t n) {
      progress.update (pcl::registration::toString (stage), done, n);
    };
    const auto prepared = pcl::io::prepareMultiviewInputs (o.views.size (), viewLoader (o.views, argc, argv, cache.get ()),
                                                           o.registration, o.threads, cache.get (), inputs, show,
                                                           cache ? sensorLookup (o.views, argc, argv, *cache)
                                                                 : pcl::io::MultiviewInputLookup ());
    kept.applyTo (inputs);
    // Pairs from the cache (or registered and kept there), and from results computed elsewhere first.
    pcl::registration::ViewPairRegistration pairs = [] (int, int, const auto& model, const auto& scene, const auto& dims,
                                                        const auto& params) {
      return pcl::registration::registerTensorViews (model, scene, dims, params);
    };
    if (cache)
    {
      pairs = pcl::io::cachedPairRegistration (*cache, prepared);
      registration.setPairScoreCache (pcl::io::cachedPairScores (*cache, prepared));
    }
    if (!o.pairs_results.empty ())
    {
      std::vector<pcl::io::ViewPairResult> recorded;
      for (const auto& file : o.pairs_results)
      {
        const auto results = pcl::io::loadViewPairResults (file);
        recorded.insert (recorded.end (), results.begin (), results.end ());
      }
      pairs = pcl::io::recordedPairRegistration (recorded, o.views, pairs);
    }
    registration.setPairRegistration (pairs);
    t.preparation_ms = timer.toc ();
    if (!o.pairs.empty ())
      registration.setPairs (pcl::io::loadViewPairs (o.pairs, o.views));
    registration.setProgressCallback (show);
    const auto result = registration.compute (inputs);

    timer.tic ();
    progress.update ("integration", 0, 1);
    std::vector<ComponentModel> models;
    for (int c = 0; c < result.components; ++c)
      models.push_back (integrateComponent (result, o, c, cache.get (), prepared, kept));
    progress.update ("integration", 1, 1);
    progress.finish ();
    t.integration_ms = timer.toc ();

    timer.tic ();
    for (std::size_t c = 0; c < models.size (); ++c)
    {
      pcl::io::saveScanMesh (models[c].model, models[c].mesh);
      saveConf (models[c].conf, result, static_cast<int> (c), kept);
    }
    t.write_ms = timer.toc ();
    t.total_ms = total.toc ();

    pcl::io::ModelRunRecord record;
    record.report = jsonSummary (result, models, t);
    record.messages = viewsLeftOut (result, models);
    record.exit_code = record.messages.empty () ? kExitModelled : pcl_tensor_tools::kExitNotRegistered;
    if (o.json)
      std::cout << record.report << std::endl;
    else
      printText (result, models, t);
    std::cerr << record.messages;
    if (cache)
    {
      for (const auto& m : models)
        for (const auto& file : {m.model, m.conf})
          record.outputs.emplace_back (file, pcl::io::hashFileContents (file));
      pcl::io::saveModelRun (*cache, run_key, record);
    }
    return record.exit_code;
  }
}

int
main (int argc, char** argv)
{
  return pcl_tensor_tools::toolMain ("pcl_tensor_model", argc, argv, printHelp, run);
}
