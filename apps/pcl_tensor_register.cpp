/*
 * pcl_tensor_register: automatic pairwise registration of two range images (Mian et al., 2006).
 */
#include "tool_main.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/common/transforms.h>
#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/console/time.h>
#include <pcl/io/point_cloud_ply.h>
#include <pcl/io/range_scan_io.h>
#include <pcl/io/registration_report_json.h>
#include <pcl/registration/tensor_registration.h>

#include <future>
#include <iostream>
#include <thread>

using namespace pcl::console;

namespace
{
  constexpr int kExitRegistered = 0;
  using pcl_tensor_tools::kExitNotRegistered;

  void
  printHelp (const char* name)
  {
    const pcl::registration::TensorRegistrationParams d;
    print_info ("Register SCENE to MODEL automatically with tensors (Mian, Bennamoun & Owens, IJCV 2006).\n\n");
    print_info ("Usage: %s MODEL.{ply,pcd} SCENE.{ply,pcd} [-o aligned.ply] [--json] [options]\n", name);
    print_info ("Prints the 4x4 transform that maps SCENE into MODEL's frame.\n\n");
    print_info ("  -o FILE            write SCENE transformed into MODEL's frame (PLY)\n");
    print_info ("  --json             print a JSON report instead of text\n");
    print_info ("  -j N               threads (default 0: every core); the result is the same for any number\n");
    print_info ("  --faces N          faces per reduced mesh (default %d)\n", d.preparation.target_faces);
    print_info ("  --grid N           tensor grid size (default %d)\n", d.grid_size);
    print_info ("  --tr T             overlap ratio threshold t_r, Eq. 5 (default %g)\n", d.overlap_threshold);
    print_info ("  --tc T             correlation threshold t_c, Eq. 6 (default %g)\n", d.correlation_threshold);
    print_info ("  --fallback T       when no match over t_r and t_c settles the pair, try those over T for both\n"
                "                     (default %g; at or above t_r and t_c: no second round)\n", d.fallback_overlap_threshold);
    print_info ("  --order best|scene  order of hypotheses (default %s)\n", pcl::registration::tensorMatchOrderName (d.order));
    print_info ("  --max-hypotheses N give up after N hypotheses, 0 = all (default %d)\n", d.max_hypotheses);
    print_info ("  --scene-batches N  compute SCENE's tensors in N batches, each verified before the next (default %d)\n",
                d.scene_tensor_batches);
    print_info ("  --ambiguity-checks N  hypotheses verified after one passes, looking for a second pose (default %d)\n",
                d.ambiguity_checks);
    print_info ("  --no-rival-probe   do not probe the rival poses a verified pose leaves open (default: probe)\n");
    print_info ("  --dims-fraction F  fine dimension check: allowed excess over D as a fraction of mean(D), at least\n"
                "                     2 d_res (0: the paper's 2 d_res alone; default %g)\n", d.verification.fine_dimension_fraction);
    print_info ("  --nc F             n_c as a fraction of the smaller view (default %g)\n", d.verification.correspondence_fraction);
    print_info ("  --icp-normal-angle A  ICP pairs points whose normals differ by at most A degrees (180: all;\n"
                "                     default %g)\n", d.verification.icp_max_normal_angle);
    print_info ("  --count both|scene views whose correspondences verification counts (default %s)\n",
                d.verification.count_both_views ? "both" : "scene");
    print_info ("  --dims X,Y,Z       object dimensions D (default: from the two views, Eq. 1)\n");
    print_info ("  --viewpoint x,y,z  perspective sensor at x,y,z looking at each scan (default: a PCD's pose; the pushbroom a PLY grid fits; else +z)\n");
    print_info ("Exit codes: 0 registered, 3 not registered (no hypothesis passed verification, or two distinct poses did),\n"
                "2 bad input or usage.\n");
  }

  pcl::registration::TensorRegistrationParams
  parseParams (int argc, char** argv)
  {
    pcl::registration::TensorRegistrationParams p;
    parse_argument (argc, argv, "--faces", p.preparation.target_faces);
    parse_argument (argc, argv, "--grid", p.grid_size);
    parse_argument (argc, argv, "--tr", p.overlap_threshold);
    parse_argument (argc, argv, "--tc", p.correlation_threshold);
    if (parse_argument (argc, argv, "--fallback", p.fallback_overlap_threshold) >= 0)
      p.fallback_correlation_threshold = p.fallback_overlap_threshold;
    parse_argument (argc, argv, "--max-hypotheses", p.max_hypotheses);
    parse_argument (argc, argv, "--scene-batches", p.scene_tensor_batches);
    parse_argument (argc, argv, "--nc", p.verification.correspondence_fraction);
    parse_argument (argc, argv, "--icp-normal-angle", p.verification.icp_max_normal_angle);
    parse_argument (argc, argv, "--ambiguity-checks", p.ambiguity_checks);
    p.probe_rivals = !find_switch (argc, argv, "--no-rival-probe");
    parse_argument (argc, argv, "--dims-fraction", p.verification.fine_dimension_fraction);
    std::string order;
    parse_argument (argc, argv, "--order", order);
    if (!order.empty ())
      p.order = pcl::registration::parseTensorMatchOrder (order);
    std::string count = p.verification.count_both_views ? "both" : "scene";
    parse_argument (argc, argv, "--count", count);
    if (count != "both" && count != "scene")
      PCL_TENSOR_THROW (pcl::BadArgumentException, "--count must be 'both' or 'scene', got '" << count << "'");
    p.verification.count_both_views = (count == "both");
    return p;
  }

  std::string
  jsonReport (const pcl::registration::TensorRegistrationReport& r, double load_ms)
  {
    pcl::io::JsonReport j = pcl::io::toJson (r);
    j["timings_ms"]["load"] = load_ms;
    return pcl::io::dumpJson (j);
  }

  void
  printText (const pcl::registration::TensorRegistrationReport& r)
  {
    if (!r.registered)
      return;  // run () says so, in one line on stderr
    print_info ("Registered after "); print_value ("%zu", r.hypotheses_tried); print_info (" hypotheses (");
    print_value ("%zu", r.matches); print_info (" matches of "); print_value ("%zu", r.scene_tensors);
    print_info (" x "); print_value ("%zu", r.model_tensors); print_info (" tensors) in "); print_value ("%g", r.timings.total_ms);
    print_info (" ms\n");
    std::cout << r.transform << std::endl;
  }

  int
  run (int argc, char** argv)
  {
    pcl_tensor_tools::keepFreedMemoryForReuse ();
    std::string output;
    parse_argument (argc, argv, "-o", output);
    const std::vector<std::string> files = pcl_tensor_tools::scanFileArguments (argc, argv, {output});
    if (files.size () != 2)
      PCL_TENSOR_THROW (pcl::BadArgumentException, "expected MODEL and SCENE files (.ply or .pcd); see --help");
    const bool json = find_switch (argc, argv, "--json");
    if (json)
      setVerbosityLevel (L_ALWAYS);

    pcl::registration::TensorRegistration registration;
    registration.setParams (parseParams (argc, argv));
    const unsigned threads = pcl_tensor_tools::parseThreads (argc, argv);
    registration.setNumberOfThreads (threads);
    pcl::ObjectDimensions dims;
    if (pcl_tensor_tools::parseObjectDimensions (argc, argv, dims.D))
      registration.setObjectDimensions (dims);

    TicToc timer;
    timer.tic ();
    // The scene is read beside the model when more than one thread may run (a model error is still the one reported).
    const bool side_by_side = threads != 1 && std::thread::hardware_concurrency () > 1;
    auto read_scene = std::async (side_by_side ? std::launch::async : std::launch::deferred,
                                  [&files] { return pcl::io::loadRangeScan (files[1]); });
    const pcl::io::RangeScan model = pcl::io::loadRangeScan (files[0]);
    const pcl::io::RangeScan scene = read_scene.get ();
    const double load_ms = timer.toc ();
    registration.setInputTarget (model.cloud);
    registration.setInputSource (scene.cloud);
    pcl::ScanViewpoint model_view = model.viewpoint, scene_view = scene.viewpoint;
    if (pcl_tensor_tools::parseViewpoint (argc, argv, *model.cloud, model_view))
      pcl_tensor_tools::parseViewpoint (argc, argv, *scene.cloud, scene_view);
    registration.setTargetViewpoint (model_view);
    registration.setSourceViewpoint (scene_view);

    pcl::PointCloud<pcl::PointXYZ> aligned;
    registration.alignOrThrow (aligned);
    const auto& report = registration.getReport ();
    if (json)
      std::cout << jsonReport (report, load_ms) << std::endl;
    else
    {
      print_info ("Loaded both scans in "); print_value ("%g", load_ms); print_info (" ms\n");
      printText (report);
    }
    if (!report.registered)
    {
      if (report.ambiguous)
        std::cerr << "pcl_tensor_register: not registered: ambiguous, two distinct poses passed verification "
                     "(a symmetric object?); --json lists both" << std::endl;
      else
        std::cerr << "pcl_tensor_register: not registered: none of " << report.hypotheses_tried
                  << " hypotheses passed verification" << std::endl;
      return kExitNotRegistered;
    }
    if (!output.empty ())
      pcl::io::savePointCloudPLY (output, aligned);
    return kExitRegistered;
  }
}

int
main (int argc, char** argv)
{
  return pcl_tensor_tools::toolMain ("pcl_tensor_register", argc, argv, printHelp, run);
}
