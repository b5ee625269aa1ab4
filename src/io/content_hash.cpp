/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/content_hash.h>
#include "file_input.h"

namespace pcl
{
  namespace io
  {
    namespace
    {
      constexpr std::uint64_t kFnvPrime = 1099511628211ull;

      std::uint64_t
      loadWord (const unsigned char* bytes)
      {
        std::uint64_t word;
        std::memcpy (&word, bytes, sizeof (word));
        return word;
      }

      /** murmur3's fmix64: every input bit reaches every output bit. */
      std::uint64_t
      finalMix (std::uint64_t h)
      {
        h ^= h >> 33;
        h *= 0xff51afd7ed558ccdull;
        h ^= h >> 33;
        h *= 0xc4ceb9fe1a85ec53ull;
        h ^= h >> 33;
        return h;
      }
    }

    void
    ContentHash::mixWord (std::uint64_t word)
    {
      // FNV-1a's step on a word; a multiplication only carries upward, so the shift brings the high
      // bits back down before the next word. Both are bijections of the state.
      state_ = (state_ ^ word) * kFnvPrime;
      state_ ^= state_ >> 29;
    }

    ContentHash&
    ContentHash::update (const void* data, std::size_t size)
    {
      const auto* bytes = static_cast<const unsigned char*> (data);
      length_ += size;
      while (size > 0 && pending_size_ > 0)
      {
        pending_[pending_size_++] = *bytes++;
        --size;
        if (pending_size_ == sizeof (pending_))
        {
          mixWord (loadWord (pending_));
          pending_size_ = 0;
        }
      }
      for (; size >= sizeof (pending_); bytes += sizeof (pending_), size -= sizeof (pending_))
        mixWord (loadWord (bytes));
      std::memcpy (pending_ + pending_size_, bytes, size);
      pending_size_ += size;
      return *this;
    }

    std::uint64_t
    ContentHash::digest () const
    {
      ContentHash last (*this);
      if (last.pending_size_ > 0)
      {
        // Zero padding is told from real zeros by the length, mixed in next.
        std::memset (last.pending_ + last.pending_size_, 0, sizeof (pending_) - last.pending_size_);
        last.mixWord (loadWord (last.pending_));
      }
      last.mixWord (length_);
      return finalMix (last.state_);
    }

    std::uint64_t
    hashBytes (std::string_view bytes)
    {
      return ContentHash ().update (bytes).digest ();
    }

    std::uint64_t
    hashFileContents (const std::string& path)
    {
      ContentHash hash;
      detail::readFileBlocks (path, [&hash] (const char* bytes, std::size_t n) { hash.update (bytes, n); });
      return hash.digest ();
    }

    std::string
    toHex (std::uint64_t value)
    {
      static const char digits[] = "0123456789abcdef";
      std::string hex (16, '0');
      for (int i = 15; i >= 0; --i, value >>= 4)
        hex[i] = digits[value & 0xf];
      return hex;
    }
  }
}
