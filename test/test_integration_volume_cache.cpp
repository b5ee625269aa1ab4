/*
 * A model's voxels kept in the cache (IntegrationVolume): they come back exactly, under their key only,
 * and an entry that is damaged, cut or of another key is never used.
 */
#include "test_utils.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/io/integration_volume_cache.h>

#include <filesystem>
#include <fstream>
#include <random>

namespace
{
  namespace fs = std::filesystem;

  /** \a blocks blocks of random voxels, fixed seed. */
  pcl::IntegrationVolume
  randomVolume (std::size_t blocks)
  {
    std::mt19937 rng (5);
    std::uniform_int_distribution<int> coordinate (-1000, 1000);
    std::uniform_real_distribution<float> value (-1.0f, 1.0f);
    pcl::IntegrationVolume v;
    v.voxel_size = 0.00123;
    v.views = 7;
    v.resolution_sum = 0.0081;
    for (std::size_t b = 0; b < blocks; ++b)
      v.blocks.emplace_back (coordinate (rng), coordinate (rng), coordinate (rng));
    for (std::size_t i = 0; i < blocks * pcl::IntegrationVolume::kBlockVoxels; ++i)
    {
      v.distance.push_back (value (rng));
      v.weight.push_back (value (rng) + 1.0f);
    }
    return v;
  }

  class IntegrationVolumeCacheTest : public ::testing::Test
  {
    protected:
      void
      SetUp () override
      {
        dir_ = fs::path (::testing::TempDir ()) /
               ("integration_volume_cache_" + std::string (::testing::UnitTest::GetInstance ()->current_test_info ()->name ()));
        fs::remove_all (dir_);
        cache_ = std::make_unique<pcl::io::TensorViewCache> (dir_.string ());
      }

      void TearDown () override { fs::remove_all (dir_); }

      /** The one entry file in the cache. */
      fs::path
      entryFile () const
      {
        for (const auto& e : fs::directory_iterator (dir_))
          if (e.path ().string ().find (".volume.tvc") != std::string::npos)
            return e.path ();
        return {};
      }

      fs::path dir_;
      std::unique_ptr<pcl::io::TensorViewCache> cache_;
      const pcl::io::TensorViewCacheKey key_{0x1234, 0x5678};
      const std::string id_ = pcl::io::integrationVolumeId ("model.conf");
  };
}

TEST_F (IntegrationVolumeCacheTest, RoundTripIsExact)
{
  const pcl::IntegrationVolume volume = randomVolume (3);
  pcl::io::saveIntegrationVolume (*cache_, id_, key_, volume);
  const auto loaded = pcl::io::loadIntegrationVolume (*cache_, id_, key_);
  ASSERT_TRUE (loaded);
  EXPECT_EQ (loaded->voxel_size, volume.voxel_size);
  EXPECT_EQ (loaded->views, volume.views);
  EXPECT_EQ (loaded->resolution_sum, volume.resolution_sum);
  EXPECT_EQ (loaded->blocks, volume.blocks);
  EXPECT_EQ (loaded->distance, volume.distance);
  EXPECT_EQ (loaded->weight, volume.weight);
}

TEST_F (IntegrationVolumeCacheTest, EmptyVolumeRoundTrips)
{
  pcl::IntegrationVolume volume;
  volume.voxel_size = 0.5;
  pcl::io::saveIntegrationVolume (*cache_, id_, key_, volume);
  const auto loaded = pcl::io::loadIntegrationVolume (*cache_, id_, key_);
  ASSERT_TRUE (loaded);
  EXPECT_TRUE (loaded->blocks.empty ());
}

TEST_F (IntegrationVolumeCacheTest, MissingStaleCutOrDamagedEntriesAreNeverUsed)
{
  EXPECT_FALSE (pcl::io::loadIntegrationVolume (*cache_, id_, key_)) << "missing";
  pcl::io::saveIntegrationVolume (*cache_, id_, key_, randomVolume (2));
  const fs::path file = entryFile ();
  ASSERT_FALSE (file.empty ());
  EXPECT_FALSE (pcl::io::loadIntegrationVolume (*cache_, id_, {key_.source, key_.preparation + 1}))
      << "the entry holds another key's voxels: stale";
  {
    // Another key's entry copied over this one: stale.
    const pcl::io::TensorViewCacheKey other{9, 9};
    pcl::io::saveIntegrationVolume (*cache_, "volume-other", other, randomVolume (1));
    fs::path other_file;
    for (const auto& e : fs::directory_iterator (dir_))
      if (e.path () != file && e.path ().string ().find (".volume.tvc") != std::string::npos)
        other_file = e.path ();
    fs::copy_file (other_file, file, fs::copy_options::overwrite_existing);
    EXPECT_FALSE (pcl::io::loadIntegrationVolume (*cache_, id_, key_)) << "stale";
  }
  pcl::io::saveIntegrationVolume (*cache_, id_, key_, randomVolume (2));
  const auto size = fs::file_size (file);
  {
    std::fstream f (file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp (static_cast<std::streamoff> (size / 2));
    f.put ('\x5a');
  }
  EXPECT_FALSE (pcl::io::loadIntegrationVolume (*cache_, id_, key_)) << "a flipped byte";
  pcl::io::saveIntegrationVolume (*cache_, id_, key_, randomVolume (2));
  fs::resize_file (file, size - 100);
  EXPECT_FALSE (pcl::io::loadIntegrationVolume (*cache_, id_, key_)) << "truncated";
}

// One entry per model's .conf: a run of the same model replaces its voxels, another model keeps its own.
TEST_F (IntegrationVolumeCacheTest, EachModelKeepsOneEntry)
{
  EXPECT_EQ (pcl::io::integrationVolumeId ("model.conf"), pcl::io::integrationVolumeId ("./model.conf"));
  EXPECT_NE (pcl::io::integrationVolumeId ("model.conf"), pcl::io::integrationVolumeId ("other.conf"));
  pcl::io::saveIntegrationVolume (*cache_, id_, key_, randomVolume (1));
  pcl::io::saveIntegrationVolume (*cache_, id_, {1, 1}, randomVolume (2));
  std::size_t entries = 0;
  for (const auto& e : fs::directory_iterator (dir_))
    entries += e.path ().string ().find (".volume.tvc") != std::string::npos ? 1 : 0;
  EXPECT_EQ (entries, 1u);
  EXPECT_FALSE (pcl::io::loadIntegrationVolume (*cache_, id_, key_)) << "replaced";
  ASSERT_TRUE (pcl::io::loadIntegrationVolume (*cache_, id_, {1, 1}));
  EXPECT_EQ (pcl::io::loadIntegrationVolume (*cache_, id_, {1, 1})->blocks.size (), 2u);
}

TEST_F (IntegrationVolumeCacheTest, InconsistentVolumeIsNotWritten)
{
  pcl::IntegrationVolume volume = randomVolume (2);
  volume.weight.pop_back ();
  EXPECT_THROW (pcl::io::saveIntegrationVolume (*cache_, id_, key_, volume), pcl::BadArgumentException);
}

// The key follows every view's key and every bit of every pose, and the integration settings.
TEST (IntegrationVolumeKey, TakesViewsPosesAndSettings)
{
  const std::vector<pcl::io::TensorViewCacheKey> views{{1, 2}, {3, 4}};
  pcl::registration::ViewPoses poses (2, Eigen::Affine3d::Identity ());
  const pcl::VolumetricIntegrationParams params;
  const auto base = pcl::io::integrationVolumeKey (views, poses, params);
  EXPECT_EQ (base, pcl::io::integrationVolumeKey (views, poses, params));
  auto moved = poses;
  moved[1].translation ().x () = std::nextafter (0.0, 1.0);
  EXPECT_NE (base, pcl::io::integrationVolumeKey (views, moved, params));
  EXPECT_NE (base, pcl::io::integrationVolumeKey ({{1, 2}, {3, 5}}, poses, params));
  EXPECT_NE (base, pcl::io::integrationVolumeKey ({{3, 4}, {1, 2}}, poses, params)) << "the order of integration";
  pcl::VolumetricIntegrationParams other = params;
  other.truncation_voxels += 1.0;
  EXPECT_NE (base, pcl::io::integrationVolumeKey (views, poses, other));
  EXPECT_THROW (pcl::io::integrationVolumeKey (views, pcl::registration::ViewPoses (1), params), pcl::BadArgumentException);
}
