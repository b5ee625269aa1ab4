/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 *
 * Private to the library: disjoint sets, for the connected pieces of meshes and point groups.
 */
#pragma once

#include <cstddef>
#include <numeric>
#include <vector>

namespace pcl
{
  namespace detail
  {
    /** Disjoint sets over 0 .. n-1: unite() links the first element's root under the second's, and
      * find() halves the paths it walks. */
    class UnionFind
    {
      public:
        explicit UnionFind (std::size_t n) : parent_ (n) { std::iota (parent_.begin (), parent_.end (), std::size_t{0}); }

        std::size_t
        find (std::size_t i)
        {
          while (parent_[i] != i)
            i = parent_[i] = parent_[parent_[i]];
          return i;
        }

        void unite (std::size_t a, std::size_t b) { parent_[find (a)] = find (b); }

      private:
        std::vector<std::size_t> parent_;
    };
  }
}
