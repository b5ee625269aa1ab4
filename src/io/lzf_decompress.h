/*
 * pcl_tensor: LZF decompression (internal; binary_compressed PCD data).
 */
#pragma once

#include <cstddef>

namespace pcl
{
  namespace io
  {
    namespace detail
    {
      /** \brief Decompress LZF data (Lehmann's format, as pcl::lzfCompress writes it) into exactly
        * \a out_size bytes. Every literal run and back reference is checked against both buffers, so
        * damaged or hostile data is refused, never read or written out of bounds. Ours rather than
        * pcl::lzfDecompress so that reading a scan does not load libpcl_io and the VTK libraries
        * behind it (about 27 ms per process).
        * \return whether \a in decompressed to exactly \a out_size bytes */
      bool
      lzfDecompress (const unsigned char* in, std::size_t in_size, unsigned char* out, std::size_t out_size);
    }
  }
}
