/*
 * pcl_tensor: what every command-line tool shares: --help, one-line errors and exit codes, and the
 * --viewpoint option.
 */
#pragma once

#include <pcl/common/scan_viewpoint.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/console/parse.h>
#include <pcl/io/range_scan_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#ifdef __GLIBC__
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace pcl_tensor_tools
{
  /** Exit code for bad input or usage, with one line on stderr. */
  constexpr int kExitBadInput = 2;
  /** Exit code when views could not be registered (verification refused every hypothesis). */
  constexpr int kExitNotRegistered = 3;

#ifdef __GLIBC__
  /** The heap grown for huge pages: more than a pair of range images takes (about 40 MB at peak). */
  constexpr std::size_t kHugePageHeap = std::size_t (128) << 20;

  /** Grows the heap by \a bytes (address space only: no page is touched) and asks the kernel to back
    * it with transparent huge pages, as glibc's own glibc.malloc.hugetlb=1 tunable would, which only
    * the environment can set. A pair of scans first touches some 10,000 pages of 4 KiB, and in a
    * virtual machine each fault costs several microseconds: the advice took about a quarter off a
    * pair's time (doc/log.md, stop 48). Where THP is off the advice changes nothing; growth beyond \a bytes gets ordinary
    * pages. It holds only while every block comes from the heap and stays there (the thresholds of
    * keepFreedMemoryForReuse()). */
  inline void
  adviseHugePages (std::size_t bytes)
  {
    constexpr std::size_t kHugePage = 2 << 20;
    const auto begin = reinterpret_cast<std::uintptr_t> (sbrk (0));
    // Freed, the block stays on the heap, as trimming waits for far more free memory. volatile: a
    // compiler may drop a malloc that is freed unused.
    void* volatile block = malloc (bytes);
    free (block);
    const auto end = reinterpret_cast<std::uintptr_t> (sbrk (0));
    const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
    if (end > first)
      madvise (reinterpret_cast<void*> (first), end - first, MADV_HUGEPAGE);
  }
#endif

  /** For a tool that runs once and must answer fast: each stage frees clouds of megabytes that the
    * next allocates again. glibc returns such blocks to the system (mmap, trim) and each page faults
    * back in; kept in the process, they are reused. pcl_tensor_register saves page faults and time
    * for a little more peak memory; pcl_tensor_model gained too little for its extra memory, so only
    * pcl_tensor_register calls it (figures: doc/log.md). The heap it then serves from is grown once
    * and advised for transparent huge pages (adviseHugePages()). */
  inline void
  keepFreedMemoryForReuse ()
  {
#ifdef __GLIBC__
    mallopt (M_MMAP_THRESHOLD, 256 << 20);
    mallopt (M_TRIM_THRESHOLD, 1 << 30);
    adviseHugePages (kHugePageHeap);
#endif
  }

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

  /** The scan files on the command line (.ply and .pcd arguments, in their order), without \a outputs
    * (the values of options such as -o, which name files too). */
  inline std::vector<std::string>
  scanFileArguments (int argc, char** argv, const std::vector<std::string>& outputs)
  {
    std::vector<int> files = pcl::console::parse_file_extension_argument (argc, argv, ".ply");
    const std::vector<int> pcds = pcl::console::parse_file_extension_argument (argc, argv, ".pcd");
    files.insert (files.end (), pcds.begin (), pcds.end ());
    std::sort (files.begin (), files.end ());
    std::vector<std::string> scans;
    for (const int i : files)
      if (std::find (outputs.begin (), outputs.end (), argv[i]) == outputs.end ())
        scans.emplace_back (argv[i]);
    return scans;
  }

  /** --dims X,Y,Z: the object's dimensions D when they are known.
    * \return false when the option is absent (\a dims is then left as it is) */
  inline bool
  parseObjectDimensions (int argc, char** argv, Eigen::Vector3d& dims)
  {
    std::vector<double> d;
    if (pcl::console::parse_x_arguments (argc, argv, "--dims", d) <= 0)
      return false;
    if (d.size () != 3 || !(d[0] > 0 && d[1] > 0 && d[2] > 0))
      PCL_TENSOR_THROW (pcl::BadArgumentException, "--dims takes three positive numbers X,Y,Z");
    dims = Eigen::Vector3d (d[0], d[1], d[2]);
    return true;
  }

  /** -j N: threads (0, the default: every core). */
  inline unsigned
  parseThreads (int argc, char** argv)
  {
    int threads = 0;
    if (pcl::console::parse_argument (argc, argv, "-j", threads) >= 0 && threads < 0)
      PCL_TENSOR_THROW (pcl::BadArgumentException, "-j takes a number of threads (0: every core), got " << threads);
    return static_cast<unsigned> (threads);
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
    viewpoint = pcl::ScanViewpoint::lookingAtScan (Eigen::Vector3d (v[0], v[1], v[2]), cloud);
    return true;
  }

  /** Fail before the work, not after it, when an output cannot be written: \a file's folder must exist. */
  inline void
  requireWritableFolder (const std::string& file)
  {
    const std::filesystem::path folder = std::filesystem::absolute (file).parent_path ();
    if (!std::filesystem::is_directory (folder))
      PCL_TENSOR_THROW (pcl::IOException, "cannot write '" << file << "': no folder " << folder);
  }

  /** One scan file read as every tool reads it (pcl::io::loadRangeScan: the file's sensor, the
    * pushbroom its grid fits, or +z), with --viewpoint's sensor instead when the option is given. */
  inline pcl::io::RangeScan
  loadScan (const std::string& file, int argc, char** argv)
  {
    pcl::io::RangeScan scan = pcl::io::loadRangeScan (file);
    parseViewpoint (argc, argv, *scan.cloud, scan.viewpoint);
    return scan;
  }
}
