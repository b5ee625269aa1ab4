#include "test_utils.h"

#include <pcl/io/cached_tensor_view.h>
#include <pcl/io/pair_score_cache.h>
#include <pcl/registration/multiview_tensor_registration.h>
#include <pcl/simulation/example_object.h>
#include <pcl/simulation/synthetic_views.h>
#include <pcl/simulation/view_set.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace
{
  namespace fs = std::filesystem;
  using namespace pcl::io;
  using namespace pcl::registration;

  class PairScoreCacheTest : public ::testing::Test
  {
    protected:
      void
      SetUp () override
      {
        const auto* info = ::testing::UnitTest::GetInstance ()->current_test_info ();
        dir_ = fs::path (::testing::TempDir ()) / ("pair_score_cache_" + std::string (info->name ()) + "_" + std::to_string (::getpid ()));
        fs::remove_all (dir_);
      }

      void
      TearDown () override
      {
        std::error_code ignored;
        fs::remove_all (dir_, ignored);
      }

      fs::path dir_;
  };

  using pcl_tensor_test::bits;

  /** Six neighbouring views 30 degrees apart on a turntable around the example object, 300 x 300. */
  const std::vector<pcl::SyntheticView>&
  ringViews ()
  {
    static const std::vector<pcl::SyntheticView> views = [] {
      pcl::SyntheticViewParams params;
      params.camera.width = params.camera.height = 300;
      auto all = pcl::renderSyntheticViews (pcl::makeExampleObject (), pcl::makeRingViewDirections (12, 30.0), params);
      all.resize (6);
      return all;
    }();
    return views;
  }

  /** Views \a order of ringViews() as registration takes them, and their cache keys. */
  void
  inputsOf (const std::vector<int>& order, std::vector<MultiviewInput>& inputs, std::vector<CachedViewReport>& entries)
  {
    const pcl::ScanPreparationParams preparation = TensorRegistrationParams ().preparation;
    for (const int i : order)
    {
      const auto& v = ringViews ()[i].view;
      inputs.push_back ({"view" + std::to_string (i), v.cloud, v.viewpoint, nullptr});
      CachedViewReport entry;
      entry.id = "view" + std::to_string (i);
      entry.key = {hashPointCloud (*v.cloud), hashPreparation (preparation, v.viewpoint)};
      entries.push_back (entry);
    }
  }

  std::vector<std::pair<TensorViewCacheKey, double>>
  someScores ()
  {
    return {{{1, 2}, 0.25}, {{3, 4}, 1.0 / 3.0}, {{5, 6}, 0.0}};
  }
}

TEST_F (PairScoreCacheTest, ScoresReadBackBitForBit)
{
  const TensorViewCache cache (dir_.string ());
  PairScoreCache first (cache);
  EXPECT_EQ (first.getLoadState (), CacheEntryState::MISSING);
  first.keep (someScores ());

  PairScoreCache second (cache);
  EXPECT_EQ (second.getLoadState (), CacheEntryState::VALID);
  EXPECT_EQ (second.size (), someScores ().size ());
  for (const auto& [key, score] : someScores ())
  {
    double found = -1.0;
    ASSERT_TRUE (second.find (key, found));
    EXPECT_EQ (bits (found), bits (score));
  }
  double none = 0.0;
  EXPECT_FALSE (second.find ({2, 1}, none)) << "a key is not its swapped halves";
}

TEST_F (PairScoreCacheTest, ADamagedEntryGivesNoScoreAndIsRewrittenWhole)
{
  const TensorViewCache cache (dir_.string ());
  PairScoreCache (cache).keep (someScores ());
  const std::string path = cache.entryPath ("pair-scores", CacheEntryKind::SCORES);
  const auto size = fs::file_size (path);
  std::string bytes (size, '\0');
  std::ifstream (path, std::ios::binary).read (bytes.data (), static_cast<std::streamsize> (size));

  std::string flipped = bytes;
  flipped[size / 2] = static_cast<char> (flipped[size / 2] ^ 0x10);
  std::ofstream (path, std::ios::binary | std::ios::trunc).write (flipped.data (), static_cast<std::streamsize> (size));
  PairScoreCache corrupt (cache);
  EXPECT_EQ (corrupt.getLoadState (), CacheEntryState::CORRUPT);
  EXPECT_EQ (corrupt.size (), 0u);

  std::ofstream (path, std::ios::binary | std::ios::trunc).write (bytes.data (), static_cast<std::streamsize> (size - 5));
  PairScoreCache truncated (cache);
  EXPECT_EQ (truncated.getLoadState (), CacheEntryState::TRUNCATED);
  EXPECT_EQ (truncated.size (), 0u);

  truncated.keep ({{{7, 8}, 0.5}});
  PairScoreCache rewritten (cache);
  EXPECT_EQ (rewritten.getLoadState (), CacheEntryState::VALID);
  EXPECT_EQ (rewritten.size (), 1u) << "nothing of the damaged entry is kept";
}

TEST_F (PairScoreCacheTest, NewScoresAreAddedToTheOld)
{
  const TensorViewCache cache (dir_.string ());
  PairScoreCache (cache).keep (someScores ());
  PairScoreCache (cache).keep ({{{7, 8}, 0.5}, {{1, 2}, 0.75}});
  PairScoreCache merged (cache);
  EXPECT_EQ (merged.size (), someScores ().size () + 1);
  double score = 0.0;
  ASSERT_TRUE (merged.find ({1, 2}, score));
  EXPECT_EQ (score, 0.75) << "a score kept again replaces the old one";
  ASSERT_TRUE (merged.find ({3, 4}, score));
  EXPECT_EQ (bits (score), bits (1.0 / 3.0));
}

TEST (PairScoreKey, IsSymmetricAndTakesEverySettingOfTheScore)
{
  const TensorViewCacheKey a{11, 12}, b{21, 22};
  pcl::ObjectDimensions dims;
  dims.D = Eigen::Vector3d (0.2, 0.15, 0.1);
  const TensorRegistrationParams params;
  const ViewPairRankingParams ranking;
  const std::uint64_t settings = hashRankingSettings (dims, params, ranking);
  const TensorViewCacheKey key = pairScoreKey (a, b, settings);
  EXPECT_EQ (key, pairScoreKey (b, a, settings)) << "the score of a pair does not depend on the views' order";
  EXPECT_NE (key, pairScoreKey (a, {21, 23}, settings));
  EXPECT_NE (key, pairScoreKey ({11, 13}, b, settings));

  std::vector<std::uint64_t> hashes{settings};
  const auto changed = [&] (const std::function<void (pcl::ObjectDimensions&, TensorRegistrationParams&, ViewPairRankingParams&)>& edit) {
    pcl::ObjectDimensions d = dims;
    TensorRegistrationParams p = params;
    ViewPairRankingParams r = ranking;
    edit (d, p, r);
    hashes.push_back (hashRankingSettings (d, p, r));
  };
  changed ([] (auto& d, auto&, auto&) { d.D[2] *= 1.01; });
  changed ([] (auto&, auto& p, auto&) { p.grid_size += 1; });
  changed ([] (auto&, auto& p, auto&) { p.overlap_threshold += 0.05; });
  changed ([] (auto&, auto& p, auto&) { p.correlation_threshold += 0.05; });
  changed ([] (auto&, auto& p, auto&) { p.theta_bin_width *= 2.0; });
  changed ([] (auto&, auto&, auto& r) { r.sample_tensors += 1; });
  changed ([] (auto&, auto&, auto& r) { r.agreement_degrees += 1.0; });
  changed ([] (auto&, auto&, auto& r) { r.agreement_distance += 0.01; });
  for (std::size_t i = 0; i < hashes.size (); ++i)
    for (std::size_t j = i + 1; j < hashes.size (); ++j)
      EXPECT_NE (hashes[i], hashes[j]) << "settings " << i << " and " << j;
  // Verification settings change no score, so a stricter check keeps the ranking's scores.
  TensorRegistrationParams stricter = params;
  stricter.verification.fine_distance *= 0.5;
  EXPECT_EQ (hashRankingSettings (dims, stricter, ranking), settings);
}

TEST_F (PairScoreCacheTest, AViewAddedScoresOnlyItsOwnPairsAndRanksAsWithoutTheCache)
{
  const TensorViewCache cache (dir_.string ());
  const auto run = [&] (const std::vector<int>& order, bool cached) {
    std::vector<MultiviewInput> inputs;
    std::vector<CachedViewReport> entries;
    inputsOf (order, inputs, entries);
    MultiviewTensorRegistration registration;
    if (cached)
      registration.setPairScoreCache (cachedPairScores (cache, entries));
    return registration.compute (inputs);
  };
  const auto first = run ({3, 0, 4, 1, 2}, true);
  EXPECT_EQ (first.candidates_scored, 10u) << "an empty cache knows no score";
  // One view added, and the others in another order: their indices change, their keys do not.
  const std::vector<int> order{2, 5, 0, 4, 1, 3};
  const auto added = run (order, true);
  EXPECT_EQ (added.candidates_scored, 5u) << "only the new view's pairs are scored";
  const auto again = run (order, true);
  EXPECT_EQ (again.candidates_scored, 0u);
  const auto uncached = run (order, false);
  EXPECT_EQ (uncached.candidates_scored, 15u);

  ASSERT_EQ (first.dimensions.D, added.dimensions.D) << "the new view leaves D as it was; else every score is new";
  ASSERT_EQ (added.registeredCount (), order.size ());
  for (const auto* r : {&added, &again})
  {
    ASSERT_EQ (r->candidates.size (), uncached.candidates.size ());
    for (std::size_t c = 0; c < uncached.candidates.size (); ++c)
    {
      EXPECT_EQ (r->candidates[c].first, uncached.candidates[c].first);
      EXPECT_EQ (r->candidates[c].second, uncached.candidates[c].second);
      EXPECT_EQ (bits (r->candidates[c].score), bits (uncached.candidates[c].score));
    }
    for (std::size_t k = 0; k < order.size (); ++k)
      EXPECT_TRUE (r->views[k].pose.matrix () == uncached.views[k].pose.matrix ()) << "view " << order[k];
  }
}
