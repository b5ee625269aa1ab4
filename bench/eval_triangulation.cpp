/*
 * eval_triangulation: the Delaunay path against the grid path (issue 2). Each scan of a Stanford .conf
 * is triangulated over its grid, then with its points shuffled (unorganized) through the retinal-plane
 * Delaunay triangulation with the same sensor; the two meshes' areas are compared.
 *
 *   eval_triangulation --conf FILE [--gap K] [--tolerance T]   (see --help)
 *
 * Third-party data is read from ../shared/data (PCL_TENSOR_SHARED_DATA) or --data DIR.
 */
#include "eval/eval_main.h"
#include "eval/eval_views.h"

#include <pcl/common/scan_mesh.h>
#include <pcl/common/time.h>
#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/surface/range_scan_triangulation.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

using namespace pcl_tensor_eval;

namespace
{
  struct Options
  {
    std::string conf;
    double gap_retinal_medians = pcl::RangeScanTriangulation ().getGapRetinalMedians ();
    double tolerance = 0.02;  ///< issue 2: the Delaunay mesh's area within 2% of the grid's
  };

  void
  printHelp (const char* name)
  {
    const Options d;
    std::printf ("Triangulates each scan of a Stanford .conf over its grid and, shuffled, through the\n"
                 "retinal-plane Delaunay triangulation; prints the ratio of the two meshes' areas.\n\n"
                 "Usage: %s --conf FILE [options]\n"
                 "       %s --bunny [options]   (the 10 bunny scans: DATA/stanford/bunny/bun.conf)\n\n"
                 "  --data DIR        third-party data (default %s)\n"
                 "  --gap K           Delaunay triangles longer than K medians on the retinal plane are left\n"
                 "                    out of the pruning statistics (default %g; inf: none)\n"
                 "  --tolerance T     count the scans whose ratio is within 1 +- T (default %g)\n",
                 name, name, PCL_TENSOR_SHARED_DATA, d.gap_retinal_medians, d.tolerance);
  }

  /** The finite points of \a cloud in a fixed random order: the scan as an unorganized cloud. */
  pcl::PointCloud<pcl::PointXYZ>
  shuffledFinitePoints (const pcl::PointCloud<pcl::PointXYZ>& cloud)
  {
    pcl::PointCloud<pcl::PointXYZ> shuffled;
    for (const auto& p : cloud)
      if (std::isfinite (p.x))
        shuffled.push_back (p);
    std::mt19937 rng (2006);
    std::shuffle (shuffled.begin (), shuffled.end (), rng);
    return shuffled;
  }

  int
  run (const Options& o)
  {
    const EvalViews scans = loadStanfordViews (o.conf);
    std::printf ("%-12s %8s %12s %12s %8s %11s\n", "scan", "points", "grid_m2", "delaunay_m2", "ratio", "delaunay_ms");
    std::size_t within = 0;
    double worst = 0.0;
    for (const auto& s : scans)
    {
      pcl::RangeScanTriangulation triangulation;
      triangulation.setViewpoint (s.viewpoint);
      triangulation.setGapRetinalMedians (o.gap_retinal_medians);
      pcl::ScanMesh grid, delaunay;
      triangulation.triangulate (*s.cloud, grid);
      const pcl::PointCloud<pcl::PointXYZ> shuffled = shuffledFinitePoints (*s.cloud);
      pcl::StopWatch watch;
      triangulation.triangulate (shuffled, delaunay);
      const double delaunay_ms = watch.getTime ();
      const double grid_area = pcl::meshArea (grid), delaunay_area = pcl::meshArea (delaunay);
      const double ratio = delaunay_area / grid_area;
      within += std::abs (ratio - 1.0) <= o.tolerance;
      worst = std::max (worst, std::abs (ratio - 1.0));
      std::printf ("%-12s %8zu %12.6f %12.6f %8.4f %11.0f\n", s.name.c_str (), s.finite_points, grid_area,
                   delaunay_area, ratio, delaunay_ms);
    }
    std::printf ("within %g of the grid's area: %zu/%zu scans; largest difference %.2f%%\n", o.tolerance, within,
                 scans.size (), 100.0 * worst);
    return 0;
  }
}

int
main (int argc, char** argv)
{
  return evalMain (argc, argv, "eval_triangulation", printHelp, [] (int argc, char** argv) {
    Options o;
    std::string data = PCL_TENSOR_SHARED_DATA;
    pcl::console::parse_argument (argc, argv, "--data", data);
    if (pcl::console::find_switch (argc, argv, "--bunny"))
      o.conf = data + "/stanford/bunny/bun.conf";
    pcl::console::parse_argument (argc, argv, "--conf", o.conf);
    pcl::console::parse_argument (argc, argv, "--gap", o.gap_retinal_medians);
    pcl::console::parse_argument (argc, argv, "--tolerance", o.tolerance);
    pcl::console::setVerbosityLevel (pcl::console::L_ERROR);
    if (o.conf.empty ())
    {
      std::fprintf (stderr, "eval_triangulation: error: give --conf FILE or --bunny\n");
      return 2;
    }
    return run (o);
  });
}
