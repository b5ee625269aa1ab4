/*
 * pcl_tensor_prepare: mesh range images (and compute their tensors) once, into a per-view cache
 * (pcl::io::TensorViewCache) that later runs find valid and keep.
 */
#include "cached_views.h"

#include <pcl/common/time.h>
#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/io/cached_tensor_view.h>
#include <pcl/io/registration_report_json.h>
#include <pcl/io/tensor_view_cache.h>
#include <pcl/registration/tensor_view.h>

#include <algorithm>
#include <iostream>

using namespace pcl::console;

namespace
{
  void
  printHelp (const char* name)
  {
    const pcl::registration::TensorRegistrationParams d;
    print_info ("Mesh range images (M_i, M'_i with normals) and optionally compute their tensors (Mian, Bennamoun &\n"
                "Owens, IJCV 2006) once, into a cache folder; a view whose entry is valid is kept, not computed again.\n\n");
    print_info ("Usage: %s VIEW.{ply,pcd}... --cache DIR [--tensors] [--dims X,Y,Z] [--only VIEW] [--json] [options]\n\n", name);
    print_info ("  --cache DIR        the cache folder (created if missing); required\n");
    print_info ("  --tensors          also each view's tensors, for D (Eq. 1) over all the views given\n");
    print_info ("  --dims X,Y,Z       with --tensors: the object's dimensions D when known (default: from all views, Eq. 1)\n");
    print_info ("  --only VIEW        with --tensors: prepare only VIEW (one of the views; may be repeated); the other views'\n"
                "                     meshes must be in the cache already and are read only for D: one job per view on\n"
                "                     many machines (scripts/pcl_tensor_dask.py)\n");
    print_info ("  --faces N          faces per reduced mesh (default %d)\n", d.preparation.target_faces);
    print_info ("  --viewpoint x,y,z  perspective sensor at x,y,z looking at each scan (default: a PCD's pose; the pushbroom a PLY grid fits; else +z)\n");
    print_info ("  -j N               threads, one view each (default 0: every core); the entries are the same for any number\n");
    print_info ("  --json             print a JSON array, one object per view, instead of text\n");
    print_info ("Prints per view (with --only: per view selected) what its entries were found as (valid, missing,\n"
                "corrupt, truncated, stale, other_version) and whether they were kept or computed.\n");
    print_info ("Exit codes: 0 every view's entries valid or written; 2 bad input or usage (with --only: also another\n"
                "view's meshes not valid in the cache).\n");
  }

  struct PrepareOptions
  {
    std::vector<std::string> views;
    /** --only: the views to prepare (all when empty). */
    std::vector<std::string> only;
    std::string cache;
    bool tensors = false;
    bool json = false;
    bool has_dims = false;
    pcl::ObjectDimensions dims;
    unsigned threads = 0;
    pcl::registration::TensorRegistrationParams params;
  };

  /** One view's run: what its entries were found as and what was done. */
  struct ViewJob : pcl_tensor_tools::CachedViewFile
  {
    /** Prepared in this run; false: another view of --only, read for D alone. */
    bool selected = true;
    /** The view when it was prepared in this run, kept for its tensors (null otherwise). */
    pcl::registration::TensorView::ConstPtr prepared;
    /** What its entries were found as, and which were computed. */
    pcl::io::CachedViewReport entries;
    double ms = 0.0;
  };

  PrepareOptions
  parseOptions (int argc, char** argv)
  {
    PrepareOptions o;
    parse_argument (argc, argv, "--cache", o.cache);
    if (o.cache.empty ())
      PCL_TENSOR_THROW (pcl::BadArgumentException, "--cache DIR is required; see --help");
    parse_multiple_arguments (argc, argv, "--only", o.only);
    o.views = pcl_tensor_tools::scanFileArguments (argc, argv, {o.cache});
    // A view named by --only is a view too: it counts once, where it stands among the others.
    for (const auto& view : o.only)
      if (const auto it = std::find (o.views.begin (), o.views.end (), view); it != o.views.end ())
        o.views.erase (it);
    if (o.views.empty ())
      PCL_TENSOR_THROW (pcl::BadArgumentException, "expected at least one VIEW file (.ply or .pcd); see --help");
    o.tensors = find_switch (argc, argv, "--tensors");
    o.json = find_switch (argc, argv, "--json");
    o.threads = pcl_tensor_tools::parseJobThreads (argc, argv);
    o.has_dims = pcl_tensor_tools::parseSortedObjectDimensions (argc, argv, o.dims);
    if (o.has_dims && !o.tensors)
      PCL_TENSOR_THROW (pcl::BadArgumentException, "--dims sets D for tensors: give --tensors too");
    if (!o.only.empty () && !o.tensors)
      PCL_TENSOR_THROW (pcl::BadArgumentException, "--only picks the views whose tensors to compute: give --tensors too");
    parse_argument (argc, argv, "--faces", o.params.preparation.target_faces);
    pcl::registration::checkParams (o.params);
    return o;
  }

  /** The view's key, and its meshes entry kept when valid, else prepared and written. */
  void
  prepareMeshes (const pcl::io::TensorViewCache& cache, const PrepareOptions& o, int argc, char** argv, ViewJob& job)
  {
    const pcl::StopWatch watch;
    const pcl::io::RangeScan scan = pcl_tensor_tools::loadScan (job.file, argc, argv);
    job.key = pcl::io::viewCacheKey (job.file, o.params.preparation, scan.viewpoint);
    try
    {
      job.prepared = pcl::io::cachedExtents (cache, job.id, job.key, *scan.cloud, scan.viewpoint, o.params.preparation,
                                             job.extents, job.entries);
    }
    catch (const pcl::InvalidScanException& e)
    {
      // Which of the views cannot be meshed, in the one line the user gets.
      PCL_TENSOR_THROW (pcl::InvalidScanException, "'" << job.file << "': " << pcl::errorDescription (e));
    }
    if (!o.tensors)
      job.prepared.reset ();
    job.ms += watch.getTime ();
  }

  /** D: --dims, or the elementwise maximum of every view's extents (Eq. 1). */
  pcl::ObjectDimensions
  objectDimensions (const PrepareOptions& o, const std::vector<ViewJob>& jobs)
  {
    return o.has_dims ? o.dims : pcl_tensor_tools::dimensionsOfViews ({jobs.begin (), jobs.end ()});
  }

  /** The views given, each selected unless --only names others. \throw pcl::BadArgumentException when
    * --only names a file that is not one of the views (by viewIdOf(), so that any path to it will do) */
  std::vector<ViewJob>
  viewJobs (const PrepareOptions& o)
  {
    std::vector<ViewJob> jobs (o.views.size ());
    for (std::size_t i = 0; i < jobs.size (); ++i)
    {
      jobs[i].file = o.views[i];
      jobs[i].id = pcl::io::viewIdOf (o.views[i]);
      jobs[i].selected = o.only.empty ();
    }
    for (const auto& view : o.only)
    {
      const std::string id = pcl::io::viewIdOf (view);
      const auto job = std::find_if (jobs.begin (), jobs.end (), [&id] (const ViewJob& j) { return j.id == id; });
      if (job == jobs.end ())
        PCL_TENSOR_THROW (pcl::BadArgumentException, "--only '" << view << "' is not one of the views given");
      job->selected = true;
    }
    return jobs;
  }

  /** A view of --only's others: its extents, from its meshes entry, for D. */
  void
  readExtents (const pcl::io::TensorViewCache& cache, const PrepareOptions& o, int argc, char** argv, ViewJob& job)
  {
    static_cast<pcl_tensor_tools::CachedViewFile&> (job) = pcl_tensor_tools::readCachedExtents (
        cache, job.file, o.params.preparation, argc, argv, "run pcl_tensor_prepare on every view first (--only needs their extents)");
  }

  /** The view's tensors entry kept when valid for \a dims, else computed (from the meshes prepared in
    * this run, or else from the cache) and written. */
  void
  prepareTensors (const pcl::io::TensorViewCache& cache, const PrepareOptions& o, const pcl::ObjectDimensions& dims,
                  ViewJob& job)
  {
    const pcl::StopWatch watch;
    pcl::io::cachedTensors (cache, job.id, job.key, dims, o.params, job.prepared.get (), job.entries);
    job.prepared.reset ();
    job.ms += watch.getTime ();
  }

  const char*
  action (bool computed)
  {
    return computed ? "computed" : "kept";
  }

  std::string
  jsonReport (const std::vector<ViewJob>& jobs, bool tensors)
  {
    pcl::io::JsonReport report = pcl::io::JsonReport::array ();
    for (const auto& job : jobs)
    {
      pcl::io::JsonReport j;
      j["file"] = job.file;
      j["id"] = job.id;
      j["meshes"] = pcl::io::toString (job.entries.meshes_found);
      j["meshes_action"] = action (job.entries.meshes_computed);
      if (tensors)
      {
        j["tensors"] = pcl::io::toString (job.entries.tensors_found);
        j["tensors_action"] = action (job.entries.tensors_computed);
      }
      j["time_ms"] = job.ms;
      report.push_back (std::move (j));
    }
    return pcl::io::dumpJson (report);
  }

  void
  printText (const std::vector<ViewJob>& jobs, bool tensors, const pcl::ObjectDimensions& dims)
  {
    for (const auto& job : jobs)
    {
      print_value ("%s", job.file.c_str ());
      print_info (": meshes %s, %s", pcl::io::toString (job.entries.meshes_found), action (job.entries.meshes_computed));
      if (tensors)
        print_info ("; tensors %s, %s", pcl::io::toString (job.entries.tensors_found), action (job.entries.tensors_computed));
      print_info ("; "); print_value ("%.0f", job.ms); print_info (" ms\n");
    }
    if (tensors)
    {
      print_info ("Tensors for D = "); print_value ("%g, %g, %g", dims.D.x (), dims.D.y (), dims.D.z ());
      print_info ("\n");
    }
  }

  int
  run (int argc, char** argv)
  {
    const PrepareOptions o = parseOptions (argc, argv);
    if (o.json)
      setVerbosityLevel (L_ALWAYS);
    const pcl::io::TensorViewCache cache (o.cache);
    std::vector<ViewJob> jobs = viewJobs (o);
    pcl_tensor_tools::forEachJob (jobs.size (), o.threads, [&] (std::size_t i) {
      if (jobs[i].selected)
        prepareMeshes (cache, o, argc, argv, jobs[i]);
      else if (!o.has_dims)
        readExtents (cache, o, argc, argv, jobs[i]);
    });
    const pcl::ObjectDimensions dims = objectDimensions (o, jobs);
    jobs.erase (std::remove_if (jobs.begin (), jobs.end (), [] (const ViewJob& j) { return !j.selected; }), jobs.end ());
    if (o.tensors)
      pcl_tensor_tools::forEachJob (jobs.size (), o.threads, [&] (std::size_t i) { prepareTensors (cache, o, dims, jobs[i]); });
    if (o.json)
      std::cout << jsonReport (jobs, o.tensors) << std::endl;
    else
      printText (jobs, o.tensors, dims);
    return 0;
  }
}

int
main (int argc, char** argv)
{
  return pcl_tensor_tools::toolMain ("pcl_tensor_prepare", argc, argv, printHelp, run);
}
