/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/integration_volume_cache.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/io/atomic_file.h>
#include <pcl/io/content_hash.h>
#include "byte_codec.h"
#include "cache_entry_file.h"

#include <filesystem>

namespace pcl
{
  namespace io
  {
    std::string
    integrationVolumeId (const std::string& poses_file)
    {
      return "volume-" + toHex (hashBytes (std::filesystem::weakly_canonical (std::filesystem::absolute (poses_file)).string ()));
    }

    TensorViewCacheKey
    integrationVolumeKey (const std::vector<TensorViewCacheKey>& views, const pcl::registration::ViewPoses& poses,
                          const VolumetricIntegrationParams& params)
    {
      if (views.size () != poses.size ())
        PCL_TENSOR_THROW (pcl::BadArgumentException, "integrationVolumeKey needs one pose per view");
      ContentHash hash, settings;
      hash.add (static_cast<std::uint64_t> (views.size ()));
      for (std::size_t i = 0; i < views.size (); ++i)
      {
        hash.add (views[i].source).add (views[i].preparation);
        for (int k = 0; k < 16; ++k)
          hash.add (poses[i].matrix ().data ()[k]);
      }
      settings.update ("integration volume");
      settings.add (params.voxel_size).add (params.voxel_size_resolutions).add (params.truncation_voxels);
      settings.add (params.border_ramp_edges).add (params.pixels_per_resolution);
      return {hash.digest (), settings.digest ()};
    }

    void
    saveIntegrationVolume (const TensorViewCache& cache, const std::string& id, const TensorViewCacheKey& key,
                           const IntegrationVolume& volume)
    {
      if (!volume.isConsistent ())
        PCL_TENSOR_THROW (pcl::BadArgumentException, "saveIntegrationVolume: the volume's sizes do not agree");
      detail::ByteWriter w;
      w.put<double> (volume.voxel_size).put<std::uint64_t> (volume.views).put<double> (volume.resolution_sum);
      w.put<std::uint64_t> (volume.blocks.size ());
      static_assert (sizeof (Eigen::Vector3i) == 3 * sizeof (std::int32_t), "blocks are written as packed coordinates");
      w.putArray (volume.blocks.empty () ? nullptr : volume.blocks.front ().data (), 3 * volume.blocks.size ());
      w.putArray (volume.distance.data (), volume.distance.size ()).putArray (volume.weight.data (), volume.weight.size ());
      writeFileAtomically (cache.entryPath (id, CacheEntryKind::VOLUME),
                           detail::encodeCacheEntry (CacheEntryKind::VOLUME, key, w.bytes ()));
    }

    IntegrationVolume::Ptr
    loadIntegrationVolume (const TensorViewCache& cache, const std::string& id, const TensorViewCacheKey& key)
    {
      const auto entry = detail::readCacheEntry (cache.entryPath (id, CacheEntryKind::VOLUME), CacheEntryKind::VOLUME, key);
      if (entry.state != CacheEntryState::VALID)
        return nullptr;
      detail::ByteReader r (entry.payload);
      auto volume = std::make_shared<IntegrationVolume> ();
      volume->voxel_size = r.get<double> ();
      volume->views = r.get<std::uint64_t> ();
      volume->resolution_sum = r.get<double> ();
      const auto blocks = r.get<std::uint64_t> ();
      if (!r.fits (blocks, 3 * sizeof (std::int32_t) + IntegrationVolume::kBlockVoxels * 2 * sizeof (float)))
        return nullptr;
      volume->blocks.resize (blocks);
      volume->distance.resize (blocks * IntegrationVolume::kBlockVoxels);
      volume->weight.resize (volume->distance.size ());
      r.getArray (volume->blocks.empty () ? nullptr : volume->blocks.front ().data (), 3 * blocks);
      r.getArray (volume->distance.data (), volume->distance.size ());
      r.getArray (volume->weight.data (), volume->weight.size ());
      if (!r.ok () || !r.atEnd () || !volume->isConsistent ())
        return nullptr;
      return volume;
    }
  }
}
