/*
 * pcl_tensor_mesh: range image -> fine mesh M_i -> reduced mesh M'_i with vertex normals (Section 2).
 */
#include "tool_main.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/console/time.h>
#include <pcl/io/scan_mesh_io.h>
#include <pcl/io/range_scan_io.h>
#include <pcl/surface/scan_preparation.h>

#include <iostream>

using namespace pcl::console;

namespace
{
  void
  printHelp (const char* name)
  {
    const pcl::ScanPreparationParams d;
    print_info ("Turn a range image into the reduced mesh M'_i of Mian et al. (2006), Section 2.\n\n");
    print_info ("Usage: %s SCAN.{ply,pcd} -o REDUCED.ply [options]\n", name);
    print_info ("  -o FILE              reduced mesh with normals (PLY)\n");
    print_info ("  --fine FILE          also write the fine mesh M_i (PLY)\n");
    print_info ("  --faces N            faces of M'_i (default "); print_value ("%d", d.target_faces); print_info (")\n");
    print_info ("  --edge-std K         prune triangles with an edge over mean + K stddev (default "); print_value ("%g", d.edge_std_devs); print_info (")\n");
    print_info ("  --normals fine|face  normal approach (b) or (a) of Section 2 (default "); print_value ("fine"); print_info (")\n");
    print_info ("  --normal-radius R    radius of approach (b), in d_res (default "); print_value ("%g", d.normal_radius_resolutions); print_info (")\n");
    print_info ("  --stray-gap G        fragments over G d_res from the rest of the scan ... (default "); print_value ("%g", d.stray_fragment_gap); print_info (")\n");
    print_info ("  --stray-fraction F   ... with under F of its points are removed; 0 keeps all (default "); print_value ("%g", d.stray_fragment_fraction); print_info (")\n");
    print_info ("  --speck-max N        groups of up to N pixels in front of the surface on every side ... (default "); print_value ("%d", d.speck_max_pixels); print_info (")\n");
    print_info ("  --speck-jump J       ... by over J grid spacings are removed; --speck-max 0 keeps all (default "); print_value ("%g", d.speck_jump); print_info (")\n");
    print_info ("  --viewpoint x,y,z    perspective sensor at x,y,z looking at the scan (default: a PCD's pose; the pushbroom a PLY grid fits; else +z)\n");
    print_info ("Exit codes: 0 done, 2 bad input or usage.\n");
  }

  /** Throws pcl::BadArgumentException so that usage errors take the same one-line path as bad data. */
  pcl::ScanPreparationParams
  parseParams (int argc, char** argv)
  {
    pcl::ScanPreparationParams params;
    parse_argument (argc, argv, "--faces", params.target_faces);
    parse_argument (argc, argv, "--edge-std", params.edge_std_devs);
    parse_argument (argc, argv, "--normal-radius", params.normal_radius_resolutions);
    parse_argument (argc, argv, "--stray-gap", params.stray_fragment_gap);
    parse_argument (argc, argv, "--stray-fraction", params.stray_fragment_fraction);
    parse_argument (argc, argv, "--speck-max", params.speck_max_pixels);
    parse_argument (argc, argv, "--speck-jump", params.speck_jump);
    std::string normals = "fine";
    parse_argument (argc, argv, "--normals", normals);
    if (normals == "face")
      params.normal_method = pcl::ScanMeshNormalEstimation::Method::FACE_AVERAGE;
    else if (normals != "fine")
      PCL_TENSOR_THROW (pcl::BadArgumentException, "--normals must be 'fine' or 'face', got '" << normals << "'");
    return params;
  }

  int
  run (int argc, char** argv)
  {
    const std::vector<int> inputs = parse_file_extension_argument (argc, argv, ".ply");
    const std::vector<int> pcds = parse_file_extension_argument (argc, argv, ".pcd");
    std::string output, fine_output;
    parse_argument (argc, argv, "-o", output);
    parse_argument (argc, argv, "--fine", fine_output);
    std::vector<int> scan_args;
    for (int i : inputs)
      if (argv[i] != output && argv[i] != fine_output)
        scan_args.push_back (i);
    scan_args.insert (scan_args.end (), pcds.begin (), pcds.end ());
    if (scan_args.size () != 1 || output.empty ())
      PCL_TENSOR_THROW (pcl::BadArgumentException, "expected one SCAN.{ply,pcd} and -o REDUCED.ply (see --help)");
    const pcl::ScanPreparationParams params = parseParams (argc, argv);

    TicToc timer;
    timer.tic ();
    pcl::io::RangeScan scan = pcl::io::loadRangeScan (argv[scan_args[0]]);
    print_info ("Loaded "); print_value ("%zu", scan.finite_points); print_info (" points in "); print_value ("%g", timer.toc ()); print_info (" ms\n");
    pcl_tensor_tools::parseViewpoint (argc, argv, *scan.cloud, scan.viewpoint);

    timer.tic ();
    const pcl::PreparedScan prepared = pcl::prepareScan (*scan.cloud, scan.viewpoint, params);
    print_info ("Meshed "); print_value ("%zu", prepared.fine.polygons.size ()); print_info (" faces (d_res ");
    print_value ("%g", prepared.resolution); print_info (") and reduced to "); print_value ("%zu", prepared.reduced.polygons.size ());
    print_info (" faces in "); print_value ("%g", timer.toc ()); print_info (" ms\n");

    timer.tic ();
    pcl::io::saveScanMesh (output, prepared.reduced);
    if (!fine_output.empty ())
      pcl::io::saveScanMesh (fine_output, prepared.fine);
    print_info ("Saved in "); print_value ("%g", timer.toc ()); print_info (" ms\n");
    return 0;
  }
}

int
main (int argc, char** argv)
{
  return pcl_tensor_tools::toolMain ("pcl_tensor_mesh", argc, argv, printHelp, run);
}
