/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 *
 * Private to the library: independent work spread over threads.
 */
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>
#include <vector>

namespace pcl
{
  namespace detail
  {
    /** The threads that a setting stands for: \a requested, or every core for 0. */
    inline unsigned
    threadCount (unsigned requested)
    {
      return requested > 0 ? requested : std::max (1u, std::thread::hardware_concurrency ());
    }

    /** Run body(i) for every i in [0, n) on up to \a threads threads (0: every core), each index once,
      * taken in order as threads come free. The caller keeps the results apart by index, so that they
      * are the same at any thread count. If bodies throw, the exception of the lowest index that ran
      * is rethrown once every thread has stopped; no new index starts after a throw. */
    template <typename Body> void
    parallelFor (std::size_t n, unsigned threads, const Body& body)
    {
      const std::size_t workers = std::min<std::size_t> (threadCount (threads), n);
      if (workers <= 1)
      {
        for (std::size_t i = 0; i < n; ++i)
          body (i);
        return;
      }
      std::atomic<std::size_t> next{0};
      std::atomic<bool> failed{false};
      std::mutex mutex;
      std::exception_ptr error;
      std::size_t error_index = std::numeric_limits<std::size_t>::max ();
      const auto work = [&] {
        for (std::size_t i; !failed && (i = next++) < n;)
          try
          {
            body (i);
          }
          catch (...)
          {
            const std::lock_guard<std::mutex> lock (mutex);
            if (i < error_index)
            {
              error = std::current_exception ();
              error_index = i;
            }
            failed = true;
          }
      };
      std::vector<std::thread> pool;
      for (std::size_t t = 1; t < workers; ++t)
        pool.emplace_back (work);
      work ();
      for (auto& thread : pool)
        thread.join ();
      if (error)
        std::rethrow_exception (error);
    }
  }
}
