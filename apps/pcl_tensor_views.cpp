/*
 * pcl_tensor_views: synthetic range images of a mesh with exact ground truth (Sections 6, 7.1, 7.5).
 *
 * A thin shell over pcl::renderSyntheticViews: load, render, save, each step timed.
 */
#include "tool_main.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/console/time.h>
#include <pcl/io/range_grid_ply.h>
#include <pcl/io/scan_mesh_io.h>
#include <pcl/io/stanford_conf.h>
#include <pcl/simulation/example_object.h>
#include <pcl/simulation/synthetic_views.h>

#include <cstdio>
#include <algorithm>
#include <filesystem>
#include <random>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace pcl::console;

namespace
{

  void
  printHelp (const char* name)
  {
    const pcl::SyntheticViewParams d;
    print_error ("Syntax is: %s MESH -o DIR [options]\n", name);
    print_info ("  MESH                  a PLY triangle mesh, or the word 'example' for the built-in object\n");
    print_info ("  -o DIR                output folder (created if needed): view_XX.ply range images (range_grid)\n");
    print_info ("                        and views.conf, their ground-truth poses (bmesh lines, Stanford convention)\n");
    print_info ("  where options are:\n");
    print_info ("    --views N           the paper's default view set; only N = 26 exists (default: "); print_value ("26"); print_info (")\n");
    print_info ("    --ring N            instead, N views on the equator (turntable)\n");
    print_info ("    --random N          add N views from random directions (uniform on the sphere, --seed)\n");
    print_info ("    --shuffle           write the views in a random order (--seed): view_XX names no longer follow the set\n");
    print_info ("    --step DEG          azimuth step of the ring in degrees (default: "); print_value ("360/N"); print_info (")\n");
    print_info ("    --noise SIGMA       Gaussian noise along the viewing direction, in d_res (default: "); print_value ("%g", d.noise_sigma_resolutions); print_info (")\n");
    print_info ("    --size W H          image size in pixels (default: "); print_value ("%d %d", d.camera.width, d.camera.height); print_info (")\n");
    print_info ("    --fov DEG           horizontal field of view in degrees (default: "); print_value ("%g", d.camera.fov_deg); print_info (")\n");
    print_info ("    --ortho             orthographic camera instead of perspective (default: "); print_value ("off"); print_info (")\n");
    print_info ("    --pushbroom         pushbroom (line-scan) camera: columns swept in parallel, each a fan of rays (default: "); print_value ("off"); print_info (")\n");
    const pcl::ScannerArtifactParams a, s = pcl::scannerLikeArtifacts ();
    print_info ("    --dropout DEG       surfaces turned more than DEG from the ray start to drop out (default: "); print_value ("%g", a.dropout_start_deg); print_info (": none)\n");
    print_info ("    --holes N           holes per view (default: "); print_value ("%d", a.holes); print_info ("), of --hole-radius PX pixels (default: "); print_value ("%g", a.hole_radius_pixels); print_info (")\n");
    print_info ("    --specks N          stray specks per view (default: "); print_value ("%d", a.specks); print_info ("), of up to --speck-pixels N (default: "); print_value ("%d", a.speck_pixels); print_info (")\n");
    print_info ("    --scanner           all of them, moderately: --dropout %g --holes %d --hole-radius %g --specks %d --speck-pixels %d\n",
                s.dropout_start_deg, s.holes, s.hole_radius_pixels, s.specks, s.speck_pixels);
    print_info ("    --seed S            seed of the noise's std::mt19937 (default: "); print_value ("%u", d.seed); print_info (")\n");
    const pcl::ExampleObjectParams e;
    print_info ("    --example-seed S    another built-in object: the seed of its bumps (default: "); print_value ("%u", e.seed); print_info (")\n");
    print_info ("    --example-size M    the built-in object's longest extent in metres (default: "); print_value ("%g", e.size); print_info (")\n");
  }

  /** The command line, checked. Throws pcl::BadArgumentException on a usage error. */
  struct Options
  {
    std::string mesh, out_dir;
    int views = 26, ring = 0, random = 0;
    bool shuffle = false;
    double step = 0.0;
    pcl::SyntheticViewParams params;
    pcl::ExampleObjectParams example;
  };

  /** A strictly parsed integer: pcl::console would read "abc" as 0 without complaint. */
  int
  toInt (const std::string& text, const char* option)
  {
    std::size_t used = 0;
    int value = 0;
    try
    {
      value = std::stoi (text, &used);
    }
    catch (const std::exception&)
    {
      used = 0;
    }
    if (used == 0 || used != text.size ())
      PCL_TENSOR_THROW (pcl::BadArgumentException, option << " expects integers, got '" << text << "'");
    return value;
  }

  /** "--size W H" as two separate arguments (pcl::console::parse_2x_arguments wants "W,H"). */
  void
  parseSize (int argc, char** argv, int& width, int& height)
  {
    const int at = find_argument (argc, argv, "--size");
    if (at < 0)
      return;
    if (at + 2 >= argc)
      PCL_TENSOR_THROW (pcl::BadArgumentException, "--size needs two values: W H");
    width = toInt (argv[at + 1], "--size");
    height = toInt (argv[at + 2], "--size");
  }

  Options
  parseOptions (int argc, char** argv)
  {
    Options o;
    if (argc < 2 || argv[1][0] == '-')
      PCL_TENSOR_THROW (pcl::BadArgumentException, "the first argument must be the MESH (a .ply file or 'example')");
    o.mesh = argv[1];
    if (parse_argument (argc, argv, "-o", o.out_dir) < 0 || o.out_dir.empty ())
      PCL_TENSOR_THROW (pcl::BadArgumentException, "missing -o DIR");
    parse_argument (argc, argv, "--views", o.views);
    parse_argument (argc, argv, "--ring", o.ring);
    if (find_switch (argc, argv, "--ring") && o.ring <= 0)
      PCL_TENSOR_THROW (pcl::BadArgumentException, "--ring needs a positive number of views");
    if (find_switch (argc, argv, "--views") && (o.views != 26 || o.ring > 0))
      PCL_TENSOR_THROW (pcl::BadArgumentException, "--views only supports 26, and excludes --ring");
    parse_argument (argc, argv, "--random", o.random);
    if (o.random < 0)
      PCL_TENSOR_THROW (pcl::BadArgumentException, "--random needs a non-negative number of views");
    o.shuffle = find_switch (argc, argv, "--shuffle");
    o.step = o.ring > 0 ? 360.0 / o.ring : 0.0;
    parse_argument (argc, argv, "--step", o.step);
    parse_argument (argc, argv, "--noise", o.params.noise_sigma_resolutions);
    parseSize (argc, argv, o.params.camera.width, o.params.camera.height);
    parse_argument (argc, argv, "--fov", o.params.camera.fov_deg);
    parse_argument (argc, argv, "--seed", o.params.seed);
    o.params.camera.orthographic = find_switch (argc, argv, "--ortho");
    o.params.camera.pushbroom = find_switch (argc, argv, "--pushbroom");
    if (find_switch (argc, argv, "--scanner"))
      o.params.artifacts = pcl::scannerLikeArtifacts ();
    parse_argument (argc, argv, "--dropout", o.params.artifacts.dropout_start_deg);
    parse_argument (argc, argv, "--holes", o.params.artifacts.holes);
    parse_argument (argc, argv, "--hole-radius", o.params.artifacts.hole_radius_pixels);
    parse_argument (argc, argv, "--specks", o.params.artifacts.specks);
    parse_argument (argc, argv, "--speck-pixels", o.params.artifacts.speck_pixels);
    parse_argument (argc, argv, "--example-seed", o.example.seed);
    parse_argument (argc, argv, "--example-size", o.example.size);
    if (!(o.example.size > 0.0))
      PCL_TENSOR_THROW (pcl::BadArgumentException, "--example-size must be positive");
    return o;
  }

  pcl::ScanMesh
  loadModel (const std::string& mesh, const pcl::ExampleObjectParams& example)
  {
    TicToc tt;
    tt.tic ();
    pcl::ScanMesh model = mesh == "example" ? pcl::makeExampleObject (example) : pcl::io::loadScanMesh (mesh);
    print_info ("Loaded "); print_value ("%s", mesh.c_str ()); print_info (" in "); print_value ("%g", tt.toc ());
    print_info (" ms: "); print_value ("%zu", model.cloud->size ()); print_info (" vertices, ");
    print_value ("%zu", model.polygons.size ()); print_info (" triangles\n");
    return model;
  }

  std::string
  viewName (std::size_t i)
  {
    std::ostringstream s;
    s << "view_" << std::setw (2) << std::setfill ('0') << i << ".ply";
    return s.str ();
  }

  void
  saveViews (const std::vector<pcl::SyntheticView>& views, const std::string& dir)
  {
    TicToc tt;
    tt.tic ();
    std::error_code ec;
    std::filesystem::create_directories (dir, ec);
    if (ec)
      PCL_TENSOR_THROW (pcl::IOException, "cannot create '" << dir << "': " << ec.message ());
    std::vector<pcl::io::StanfordConfEntry> entries;
    for (std::size_t i = 0; i < views.size (); ++i)
    {
      pcl::io::saveRangeGridPLY (dir + "/" + viewName (i), *views[i].view.cloud);
      entries.push_back (pcl::io::StanfordConfEntry::fromPose (viewName (i), views[i].view.pose));
    }
    pcl::io::saveStanfordConf (dir + "/views.conf", entries);
    print_info ("Saved "); print_value ("%zu", views.size ()); print_info (" views and views.conf to ");
    print_value ("%s", dir.c_str ()); print_info (" in "); print_value ("%g", tt.toc ()); print_info (" ms\n");
  }

  int
  run (int argc, char** argv)
  {
    const Options o = parseOptions (argc, argv);
    const pcl::ScanMesh model = loadModel (o.mesh, o.example);
    auto directions = o.ring > 0 ? pcl::makeRingViewDirections (o.ring, o.step, 0.0, o.params.up)
                                 : pcl::makeDefaultViewDirections (o.params.up);
    for (const auto& d : pcl::makeRandomViewDirections (o.random, o.params.seed))
      directions.push_back (d);
    if (o.shuffle)
      std::shuffle (directions.begin (), directions.end (), std::mt19937 (o.params.seed));
    TicToc tt;
    tt.tic ();
    const auto views = pcl::renderSyntheticViews (model, directions, o.params);
    print_info ("Rendered "); print_value ("%zu", views.size ()); print_info (" views of ");
    print_value ("%dx%d", o.params.camera.width, o.params.camera.height); print_info (" in ");
    print_value ("%g", tt.toc ()); print_info (" ms (d_res of view 0: "); print_value ("%g", views.front ().resolution);
    print_info (")\n");
    saveViews (views, o.out_dir);
    return 0;
  }
}

int
main (int argc, char** argv)
{
  return pcl_tensor_tools::toolMain ("pcl_tensor_views", argc, argv, printHelp, run);
}
