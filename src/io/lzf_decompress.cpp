/*
 * pcl_tensor: LZF decompression (internal; binary_compressed PCD data).
 */
#include "lzf_decompress.h"

namespace pcl
{
  namespace io
  {
    namespace detail
    {
      bool
      lzfDecompress (const unsigned char* in, std::size_t in_size, unsigned char* out, std::size_t out_size)
      {
        std::size_t ip = 0, op = 0;
        while (ip < in_size)
        {
          const unsigned ctrl = in[ip++];
          if (ctrl < 32)  // a literal run of ctrl + 1 bytes
          {
            const std::size_t run = ctrl + 1;
            if (run > in_size - ip || run > out_size - op)
              return false;
            for (std::size_t k = 0; k < run; ++k)
              out[op++] = in[ip++];
            continue;
          }
          // A back reference: length (3 bits, 7 = one more byte follows) and a 13-bit distance.
          std::size_t length = ctrl >> 5;
          if (length == 7)
          {
            if (ip >= in_size)
              return false;
            length += in[ip++];
          }
          length += 2;
          if (ip >= in_size)
            return false;
          const std::size_t distance = ((static_cast<std::size_t> (ctrl & 0x1f) << 8) | in[ip++]) + 1;
          if (distance > op || length > out_size - op)
            return false;
          // Byte by byte: a reference may overlap the bytes it produces (a repeated run).
          for (std::size_t k = 0; k < length; ++k, ++op)
            out[op] = out[op - distance];
        }
        return op == out_size;
      }
    }
  }
}
