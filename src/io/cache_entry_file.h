/*
 * pcl_tensor: the frame of a cache entry file: header, payload, checksum (internal; TensorViewCache).
 */
#pragma once

#include <pcl/io/tensor_view_cache.h>

#include <cstddef>
#include <limits>
#include <string>
#include <string_view>

namespace pcl
{
  namespace io
  {
    namespace detail
    {
      /** \brief What readCacheEntry() found, and the payload (or its first bytes) when VALID. */
      struct CacheEntryRead
      {
        CacheEntryState state = CacheEntryState::MISSING;
        std::string payload;
      };

      /** \brief The bytes of one entry file (tensor_view_cache.h gives the layout). */
      std::string
      encodeCacheEntry (CacheEntryKind kind, const TensorViewCacheKey& key, std::string_view payload);

      /** \brief Read and check the entry at \a path, keeping the first \a keep bytes of its payload.
        * Every byte goes through the checksum; nothing larger than the file is allocated.
        * \throw pcl::IOException when the file exists but cannot be opened or read */
      CacheEntryRead
      readCacheEntry (const std::string& path, CacheEntryKind kind, const TensorViewCacheKey& key,
                      std::size_t keep = std::numeric_limits<std::size_t>::max ());
    }
  }
}
