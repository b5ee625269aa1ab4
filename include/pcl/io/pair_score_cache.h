/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/io/tensor_view_cache.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace pcl
{
  namespace io
  {
    /** \brief The ranking scores of view pairs (ViewPairRanking::score()) kept in a cache folder, so that a
      * run with views added scores only the pairs that are new.
      *
      * All of a folder's scores are one entry, `pair-scores.scores.tvc` (CacheEntryKind::SCORES, the
      * layout of TensorViewCache with the key {0, 0}); its payload is a u64 count, then per score its
      * pairScoreKey() (u64 source, u64 preparation) and the score (f64). Scores are read when the object
      * is made and written, atomically, by keep(). An entry that is not VALID reads as no score at all:
      * each is then computed again, never trusted. Two processes keeping scores at once leave the last
      * one's file whole; the other's scores are computed again when next needed.
      * \ingroup io
      */
    class PairScoreCache
    {
      public:
        /** \brief At most this many scores are written: those used or kept by this object first, then older
          * ones, so that a folder used for many sets of views stays bounded (24 bytes a score). */
        static constexpr std::size_t MAX_SCORES = std::size_t (1) << 20;

        /** \brief The scores of \a cache, read now.
          * \throw pcl::IOException when the entry exists but cannot be read (permissions, a device error) */
        explicit PairScoreCache (const TensorViewCache& cache);

        /** \brief What the entry was when it was read (MISSING the first time). */
        CacheEntryState getLoadState () const { return state_; }

        /** \brief Scores known. */
        std::size_t size () const { return scores_.size (); }

        /** \brief The score of \a key into \a score, when known. Not thread-safe. */
        bool find (const TensorViewCacheKey& key, double& score);

        /** \brief Add \a scores (key, score) and write the entry.
          * \throw pcl::IOException when it cannot be written */
        void keep (const std::vector<std::pair<TensorViewCacheKey, double>>& scores);

      private:
        struct KeyHash
        {
          std::size_t
          operator() (const TensorViewCacheKey& k) const
          {
            return static_cast<std::size_t> (k.source ^ (k.preparation * 0x9e3779b97f4a7c15ull));
          }
        };
        struct Score
        {
          TensorViewCacheKey key;
          double score;
          bool used;  ///< found or kept through this object
        };

        std::string path_;
        CacheEntryState state_ = CacheEntryState::MISSING;
        std::vector<Score> scores_;
        std::unordered_map<TensorViewCacheKey, std::size_t, KeyHash> index_;
    };
  }
}
