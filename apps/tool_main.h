/*
 * pcl_tensor: what every command-line tool shares: --help, one-line errors and exit codes, and the
 * --viewpoint option.
 */
#pragma once

#include <pcl/common/scan_viewpoint.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/console/parse.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <iostream>
#include <vector>

namespace pcl_tensor_tools
{
  /** Exit code for bad input or usage, with one line on stderr. */
  constexpr int kExitBadInput = 2;
  /** Exit code when views could not be registered (verification refused every hypothesis). */
  constexpr int kExitNotRegistered = 3;

  /** Run a tool: --help (or no argument) prints \a help; a pcl::PCLException from \a run becomes one
    * line on stderr and exit code 2; any other exception is an internal error (exit code 1). */
  template <typename Help, typename Run> int
  toolMain (const char* name, int argc, char** argv, Help help, Run run)
  {
    if (argc < 2 || pcl::console::find_switch (argc, argv, "-h") || pcl::console::find_switch (argc, argv, "--help"))
    {
      help (argv[0]);
      return argc < 2 ? kExitBadInput : 0;
    }
    try
    {
      return run (argc, argv);
    }
    catch (const pcl::PCLException& e)
    {
      std::cerr << name << ": error: " << pcl::errorDescription (e) << std::endl;
      return kExitBadInput;
    }
    catch (const std::exception& e)
    {
      std::cerr << name << ": internal error: " << e.what () << std::endl;
      return 1;
    }
  }

  /** --viewpoint x,y,z: a perspective sensor at that point, looking at the centroid of \a cloud.
    * \return false when the option is absent (\a viewpoint is then left as it is) */
  inline bool
  parseViewpoint (int argc, char** argv, const pcl::PointCloud<pcl::PointXYZ>& cloud, pcl::ScanViewpoint& viewpoint)
  {
    std::vector<double> v;
    if (pcl::console::parse_x_arguments (argc, argv, "--viewpoint", v) <= 0)
      return false;
    if (v.size () != 3)
      PCL_TENSOR_THROW (pcl::BadArgumentException, "--viewpoint takes x,y,z");
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero ();
    std::size_t n = 0;
    for (const auto& p : cloud)
      if (std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z))
      {
        centroid += p.getVector3fMap ().cast<double> ();
        ++n;
      }
    if (n == 0)
      PCL_TENSOR_THROW (pcl::InvalidScanException, "the scan has no finite point to look at");
    viewpoint = pcl::ScanViewpoint::lookingAt (Eigen::Vector3d (v[0], v[1], v[2]), centroid / static_cast<double> (n));
    return true;
  }
}
