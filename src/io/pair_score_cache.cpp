/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/pair_score_cache.h>
#include <pcl/io/atomic_file.h>
#include "byte_codec.h"
#include "cache_entry_file.h"

namespace pcl
{
  namespace io
  {
    namespace
    {
      /** The entry's own key: its scores carry theirs. */
      const TensorViewCacheKey kEntryKey{0, 0};
      constexpr std::size_t kScoreBytes = 3 * sizeof (std::uint64_t);
    }

    PairScoreCache::PairScoreCache (const TensorViewCache& cache)
      : path_ (cache.entryPath ("pair-scores", CacheEntryKind::SCORES))
    {
      const auto entry = detail::readCacheEntry (path_, CacheEntryKind::SCORES, kEntryKey);
      state_ = entry.state;
      if (state_ != CacheEntryState::VALID)
        return;
      detail::ByteReader r (entry.payload);
      const auto count = r.get<std::uint64_t> ();
      if (!r.fits (count, kScoreBytes))
      {
        state_ = CacheEntryState::CORRUPT;
        return;
      }
      scores_.reserve (count);
      for (std::uint64_t i = 0; i < count; ++i)
      {
        Score s;
        s.key.source = r.get<std::uint64_t> ();
        s.key.preparation = r.get<std::uint64_t> ();
        s.score = r.get<double> ();
        s.used = false;
        if (index_.emplace (s.key, scores_.size ()).second)
          scores_.push_back (s);
      }
      if (!r.ok () || !r.atEnd ())
      {
        // The checksum matched, yet the payload is not ours: trust none of it.
        state_ = CacheEntryState::CORRUPT;
        scores_.clear ();
        index_.clear ();
      }
    }

    bool
    PairScoreCache::find (const TensorViewCacheKey& key, double& score)
    {
      const auto it = index_.find (key);
      if (it == index_.end ())
        return false;
      Score& s = scores_[it->second];
      s.used = true;
      score = s.score;
      return true;
    }

    void
    PairScoreCache::keep (const std::vector<std::pair<TensorViewCacheKey, double>>& scores)
    {
      for (const auto& [key, score] : scores)
      {
        const auto [it, added] = index_.emplace (key, scores_.size ());
        if (added)
          scores_.push_back ({key, score, true});
        else
          scores_[it->second] = {key, score, true};
      }
      detail::ByteWriter w;
      std::uint64_t written = 0;
      const std::size_t count = std::min (scores_.size (), MAX_SCORES);
      w.put<std::uint64_t> (count);
      // Those of this run first, then older ones while there is room.
      for (const bool used : {true, false})
        for (const Score& s : scores_)
          if (s.used == used && written < count)
          {
            w.put (s.key.source).put (s.key.preparation).put (s.score);
            ++written;
          }
      writeFileAtomically (path_, detail::encodeCacheEntry (CacheEntryKind::SCORES, kEntryKey, w.bytes ()));
    }
  }
}
