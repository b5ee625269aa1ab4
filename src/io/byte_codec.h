/*
 * pcl_tensor: little-endian fixed-width fields in and out of a byte string (internal; the cache files).
 */
#pragma once

#include <pcl/io/content_hash.h>  // the little-endian check

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>

namespace pcl
{
  namespace io
  {
    namespace detail
    {
      /** \brief Appends numbers as their little-endian bytes (floating point by bit pattern). */
      class ByteWriter
      {
        public:
          template <typename T> ByteWriter&
          put (T value)
          {
            static_assert (std::is_arithmetic<T>::value, "put() writes numbers");
            char bytes[sizeof (T)];
            std::memcpy (bytes, &value, sizeof (T));
            out_.append (bytes, sizeof (T));
            return *this;
          }

          /** \a count numbers at once, as put() writes each. */
          template <typename T> ByteWriter&
          putArray (const T* values, std::size_t count)
          {
            static_assert (std::is_arithmetic<T>::value, "putArray() writes numbers");
            if (count > 0)
              out_.append (reinterpret_cast<const char*> (values), count * sizeof (T));
            return *this;
          }

          /** A length (u64), then the bytes. */
          ByteWriter&
          putString (std::string_view s)
          {
            put<std::uint64_t> (s.size ());
            out_.append (s.data (), s.size ());
            return *this;
          }

          std::string& bytes () { return out_; }

        private:
          std::string out_;
      };

      /** \brief Reads what ByteWriter wrote. A read past the end fails: it returns zero and ok()
        * turns false for good, so a decoder checks once, at the end; fits() guards every count before
        * anything is allocated for it. */
      class ByteReader
      {
        public:
          explicit ByteReader (std::string_view bytes) : bytes_ (bytes) {}

          template <typename T> T
          get ()
          {
            static_assert (std::is_arithmetic<T>::value, "get() reads numbers");
            T value{};
            if (!ok_ || bytes_.size () - pos_ < sizeof (T))
            {
              ok_ = false;
              return value;
            }
            std::memcpy (&value, bytes_.data () + pos_, sizeof (T));
            pos_ += sizeof (T);
            return value;
          }

          /** \a count numbers at once into \a values, as get() reads each; false (for good) past the end. */
          template <typename T> bool
          getArray (T* values, std::size_t count)
          {
            static_assert (std::is_arithmetic<T>::value, "getArray() reads numbers");
            if (!fits (count, sizeof (T)))
              return false;
            if (count > 0)
              std::memcpy (values, bytes_.data () + pos_, count * sizeof (T));
            pos_ += count * sizeof (T);
            return true;
          }

          /** True when \a count elements of \a element_size bytes can still be read; false (for good) otherwise. */
          bool
          fits (std::uint64_t count, std::size_t element_size)
          {
            ok_ = ok_ && count <= (bytes_.size () - pos_) / element_size;
            return ok_;
          }

          /** A length (u64) and that many bytes. */
          std::string
          getString ()
          {
            const auto size = get<std::uint64_t> ();
            if (!fits (size, 1))
              return {};
            std::string s (bytes_.substr (pos_, size));
            pos_ += size;
            return s;
          }

          bool ok () const { return ok_; }
          bool atEnd () const { return pos_ == bytes_.size (); }

        private:
          std::string_view bytes_;
          std::size_t pos_{0};
          bool ok_{true};
      };
    }
  }
}
