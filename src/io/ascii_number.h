/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 *
 * Internal: numbers as the PLY and PCD readers take them from text and from binary doubles.
 */
#pragma once

#include <charconv>
#include <cstdlib>
#include <limits>
#include <string>

namespace pcl
{
  namespace io
  {
    namespace detail
    {
      /** A double as float, out-of-range values as infinities: a plain cast of a value beyond
        * FLT_MAX is undefined behaviour (UBSan's float-cast-overflow). */
      inline float
      toFloat (double value)
      {
        constexpr double largest = std::numeric_limits<float>::max ();
        if (value > largest || value < -largest)
          return value > 0 ? std::numeric_limits<float>::infinity () : -std::numeric_limits<float>::infinity ();
        return static_cast<float> (value);
      }

      /** The float written in [first, last) ("nan" and "inf" included); false when it is not a number.
        * Denormals and overflow give what a strtod-based reader (PCL's) gives. */
      inline bool
      parseFloat (const char* first, const char* last, float& value)
      {
        // from_chars does not accept a leading '+', which some writers emit.
        const char* start = (first != last && *first == '+') ? first + 1 : first;
        const auto result = std::from_chars (start, last, value);
        if (result.ec == std::errc::result_out_of_range)
        {
          value = toFloat (std::strtod (std::string (start, last).c_str (), nullptr));
          return true;
        }
        return result.ec == std::errc () && result.ptr == last;
      }
    }
  }
}
