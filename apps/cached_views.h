/*
 * pcl_tensor: what the tools that read the per-view cache share (pcl_tensor_prepare, pcl_tensor_pairs):
 * jobs on threads, each view's key and cached extents, and D from them.
 */
#pragma once

#include "tool_main.h"

#include <pcl/io/cached_tensor_view.h>
#include <pcl/io/tensor_view_cache.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <thread>

namespace pcl_tensor_tools
{
  /** \a work (i) for every i < \a n on \a threads threads, one job at a time each; a job's failure does
    * not stop the others, and the first failure in job order is rethrown once all are done, so the
    * message does not depend on the threads. */
  inline void
  forEachJob (std::size_t n, unsigned threads, const std::function<void (std::size_t)>& work)
  {
    std::vector<std::exception_ptr> failures (n);
    std::atomic<std::size_t> next{0};
    const auto worker = [&] {
      for (std::size_t i = next++; i < n; i = next++)
        try
        {
          work (i);
        }
        catch (...)
        {
          failures[i] = std::current_exception ();
        }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < std::min<std::size_t> (threads, n); ++t)
      pool.emplace_back (worker);
    worker ();
    for (auto& t : pool)
      t.join ();
    for (const auto& failure : failures)
      if (failure)
        std::rethrow_exception (failure);
  }

  /** -j N with 0 (the default) as every core. */
  inline unsigned
  parseJobThreads (int argc, char** argv)
  {
    const unsigned threads = parseThreads (argc, argv);
    return threads > 0 ? threads : std::max (1u, std::thread::hardware_concurrency ());
  }

  /** --dims X,Y,Z sorted from largest to smallest, as Eq. 1 gives D, so that tensors computed for a
    * given D are found again whatever order it was written in.
    * \return false when the option is absent */
  inline bool
  parseSortedObjectDimensions (int argc, char** argv, pcl::ObjectDimensions& dims)
  {
    Eigen::Vector3d given;
    if (!parseObjectDimensions (argc, argv, given))
      return false;
    dims = pcl::givenObjectDimensions (given);
    return true;
  }

  /** One view file as the cache knows it. */
  struct CachedViewFile
  {
    std::string file;
    /** Its entries' name (pcl::io::viewIdOf()). */
    std::string id;
    pcl::io::TensorViewCacheKey key;
    /** Its principal extents, from its meshes entry (Eq. 1 for one view). */
    Eigen::Vector3d extents = Eigen::Vector3d::Zero ();
  };

  /** Throw pcl::IOException naming the view when its \a entry ("meshes", "tensors") is not valid. */
  inline void
  requireValidEntry (pcl::io::CacheEntryState state, const std::string& file, const char* entry,
                     const pcl::io::TensorViewCache& cache, const char* remedy)
  {
    if (state != pcl::io::CacheEntryState::VALID)
      PCL_TENSOR_THROW (pcl::IOException, "'" << file << "': its " << entry << " are " << pcl::io::toString (state)
                        << " in the cache '" << cache.getDirectory () << "': " << remedy);
  }

  /** The key and extents of a view whose meshes another run put in \a cache. The scan is read, since
    * its sensor (the file's, or --viewpoint's) is part of the key.
    * \throw pcl::IOException when its meshes entry is not VALID (\a remedy says what to run) */
  inline CachedViewFile
  readCachedExtents (const pcl::io::TensorViewCache& cache, const std::string& file,
                     const pcl::ScanPreparationParams& preparation, int argc, char** argv, const char* remedy)
  {
    CachedViewFile view;
    view.file = file;
    view.id = pcl::io::viewIdOf (file);
    const pcl::io::RangeScan scan = loadScan (file, argc, argv);
    view.key = pcl::io::viewCacheKey (file, preparation, scan.viewpoint);
    requireValidEntry (cache.loadExtents (view.id, view.key, view.extents), file, "meshes", cache, remedy);
    return view;
  }

  /** D from the views' extents (Eq. 1: their elementwise maximum), as MultiviewTensorRegistration and
    * pcl_tensor_prepare --tensors take it. */
  inline pcl::ObjectDimensions
  dimensionsOfViews (const std::vector<CachedViewFile>& views)
  {
    std::vector<Eigen::Vector3d> extents;
    for (const auto& view : views)
      extents.push_back (view.extents);
    return pcl::objectDimensionsFromExtents (extents);
  }
}
