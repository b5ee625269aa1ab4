/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>

// add() and the cache format take a number's bytes in memory as its little-endian bytes.
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "pcl_tensor's content hashes and cache files assume a little-endian machine"
#endif

namespace pcl
{
  namespace io
  {
    /** \brief A fast, non-cryptographic 64-bit hash of a byte stream, for checksums and cache keys.
      *
      * FNV-1a over 64-bit little-endian words instead of bytes (eight times fewer multiplications),
      * each step followed by an xor-shift, and murmur3's 64-bit finalizer over the state and the
      * length. Each step is a bijection of the state for a given word and changes the state for any
      * other word, so two streams of equal length that differ in one 8-byte word, and hence in one
      * byte, always hash differently. It does not resist deliberate collisions.
      *
      * The digest depends only on the bytes, not on how they are split among update() calls.
      * \ingroup io
      */
    class ContentHash
    {
      public:
        /** \brief Add \a size bytes at \a data. */
        ContentHash& update (const void* data, std::size_t size);

        /** \brief Add \a bytes. */
        ContentHash& update (std::string_view bytes) { return update (bytes.data (), bytes.size ()); }

        /** \brief Add an integer, an enum, a float or a double as its little-endian bytes (floating
          * point by its bit pattern, so that -0.0 and 0.0, or two NaNs, are told apart). */
        template <typename T> ContentHash&
        add (T value)
        {
          static_assert (std::is_arithmetic<T>::value || std::is_enum<T>::value, "add() takes numbers; update() bytes");
          unsigned char bytes[sizeof (T)];
          std::memcpy (bytes, &value, sizeof (T));
          return update (bytes, sizeof (T));
        }

        /** \brief The hash of every byte added so far (more may be added afterwards). */
        std::uint64_t digest () const;

      private:
        void mixWord (std::uint64_t word);

        std::uint64_t state_{14695981039346656037ull};  // FNV-1a's offset basis
        std::uint64_t length_{0};
        unsigned char pending_[8] = {};
        std::size_t pending_size_{0};
    };

    /** \brief ContentHash of \a bytes. \ingroup io */
    std::uint64_t
    hashBytes (std::string_view bytes);

    /** \brief ContentHash of the bytes of the file at \a path, read in blocks.
      * \throw pcl::IOException when it cannot be opened or read
      * \ingroup io
      */
    std::uint64_t
    hashFileContents (const std::string& path);

    /** \brief \a value as 16 lowercase hexadecimal digits. \ingroup io */
    std::string
    toHex (std::uint64_t value);
  }
}
