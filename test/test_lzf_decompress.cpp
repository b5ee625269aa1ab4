/*
 * pcl_tensor: the LZF decoder gives back exactly what pcl::lzfCompress compressed, and refuses damaged
 * data (cut short, a reference before the start, more bytes than the output holds) without reading or
 * writing out of bounds.
 */
#include "io/lzf_decompress.h"

#include <pcl/io/lzf.h>

#include <gtest/gtest.h>

#include <random>
#include <vector>

using pcl::io::detail::lzfDecompress;

namespace
{
  std::vector<unsigned char>
  compress (const std::vector<unsigned char>& raw)
  {
    std::vector<unsigned char> packed (raw.size () * 2 + 64);
    const unsigned n = pcl::lzfCompress (raw.data (), static_cast<unsigned> (raw.size ()), packed.data (),
                                         static_cast<unsigned> (packed.size ()));
    packed.resize (n);
    return packed;
  }

  /** Float grids like a PCD's: runs of equal values (references, long ones too) between noisy ones (literals). */
  std::vector<unsigned char>
  scanLikeBytes (std::size_t floats, unsigned seed)
  {
    std::mt19937 rng (seed);
    std::uniform_real_distribution<float> value (-1.0f, 1.0f);
    std::vector<float> v (floats);
    for (std::size_t i = 0; i < floats; ++i)
      v[i] = (i / 300) % 2 == 0 ? 0.25f : value (rng);
    const auto* bytes = reinterpret_cast<const unsigned char*> (v.data ());
    return std::vector<unsigned char> (bytes, bytes + v.size () * sizeof (float));
  }
}

TEST (LzfDecompress, GivesBackWhatPclCompressed)
{
  for (const unsigned seed : {1u, 2u, 3u})
  {
    const auto raw = scanLikeBytes (5000 * seed, seed);
    const auto packed = compress (raw);
    ASSERT_GT (packed.size (), 0u);
    ASSERT_LT (packed.size (), raw.size ()) << "the runs must compress";
    std::vector<unsigned char> out (raw.size (), 0xAB);
    ASSERT_TRUE (lzfDecompress (packed.data (), packed.size (), out.data (), out.size ()));
    EXPECT_EQ (out, raw);
    // PCL's own decoder agrees.
    std::vector<unsigned char> pcl_out (raw.size ());
    EXPECT_EQ (pcl::lzfDecompress (packed.data (), static_cast<unsigned> (packed.size ()), pcl_out.data (),
                                   static_cast<unsigned> (pcl_out.size ())), raw.size ());
    EXPECT_EQ (pcl_out, raw);
  }
}

TEST (LzfDecompress, OverlappingReferenceRepeatsARun)
{
  // A literal 'a', then a reference one byte back of length 9 (ctrl 7 << 5 | 0, extra 0 -> 7 + 2):
  // ten 'a's in all.
  const std::vector<unsigned char> packed = {0x00, 'a', 0xE0, 0x00, 0x00};
  std::vector<unsigned char> out (10);
  ASSERT_TRUE (lzfDecompress (packed.data (), packed.size (), out.data (), out.size ()));
  EXPECT_EQ (out, std::vector<unsigned char> (10, 'a'));
}

TEST (LzfDecompress, RefusesDamagedData)
{
  const auto raw = scanLikeBytes (4000, 9);
  const auto packed = compress (raw);
  std::vector<unsigned char> out (raw.size ());
  // Cut short: the output is not filled (or a run or reference lacks its bytes).
  for (const std::size_t cut : {std::size_t (1), std::size_t (2), packed.size () / 2, packed.size () - 1})
    EXPECT_FALSE (lzfDecompress (packed.data (), cut, out.data (), out.size ())) << "cut to " << cut;
  // The output is smaller than the data: refused before writing past it.
  std::vector<unsigned char> small (raw.size () / 2);
  EXPECT_FALSE (lzfDecompress (packed.data (), packed.size (), small.data (), small.size ()));
  // Larger than the data: not filled.
  std::vector<unsigned char> large (raw.size () + 1);
  EXPECT_FALSE (lzfDecompress (packed.data (), packed.size (), large.data (), large.size ()));
  // A reference before the first byte.
  const std::vector<unsigned char> before_start = {0x00, 'a', 0x20, 0x05};
  EXPECT_FALSE (lzfDecompress (before_start.data (), before_start.size (), out.data (), 4));
  // A reference's length byte or distance byte missing.
  const std::vector<unsigned char> no_length = {0x00, 'a', 0xE0};
  EXPECT_FALSE (lzfDecompress (no_length.data (), no_length.size (), out.data (), 10));
  const std::vector<unsigned char> no_distance = {0x00, 'a', 0x20};
  EXPECT_FALSE (lzfDecompress (no_distance.data (), no_distance.size (), out.data (), 4));
  // Nothing in, nothing out.
  EXPECT_TRUE (lzfDecompress (packed.data (), 0, out.data (), 0));
}
