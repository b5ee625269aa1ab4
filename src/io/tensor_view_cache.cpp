/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/tensor_view_cache.h>
#include <pcl/io/atomic_file.h>
#include <pcl/common/tensor_exceptions.h>
#include "cache_entry_file.h"
#include "registration_report_codec.h"
#include "tensor_view_codec.h"

#include <cstring>
#include <filesystem>

namespace pcl
{
  namespace io
  {
    namespace
    {
      bool
      sameBits (const Eigen::Vector3d& a, const Eigen::Vector3d& b)
      {
        return std::memcmp (a.data (), b.data (), sizeof (double) * 3) == 0;
      }
    }

    const char*
    toString (CacheEntryState state)
    {
      switch (state)
      {
        case CacheEntryState::VALID: return "valid";
        case CacheEntryState::MISSING: return "missing";
        case CacheEntryState::CORRUPT: return "corrupt";
        case CacheEntryState::TRUNCATED: return "truncated";
        case CacheEntryState::STALE: return "stale";
        case CacheEntryState::OTHER_VERSION: return "other_version";
      }
      return "unknown";
    }

    TensorViewCache::TensorViewCache (const std::string& dir) : dir_ (dir)
    {
      std::error_code ec;
      std::filesystem::create_directories (dir, ec);
      if (!std::filesystem::is_directory (dir))
        PCL_TENSOR_THROW (pcl::IOException, "cannot use '" << dir << "' as a cache folder"
                          << (ec ? ": " + ec.message () : std::string (": not a folder")));
    }

    std::string
    TensorViewCache::entryPath (const std::string& view_id, CacheEntryKind kind) const
    {
      if (!isValidViewId (view_id))
        PCL_TENSOR_THROW (pcl::BadArgumentException, "'" << view_id << "' cannot name a cache entry (see isValidViewId)");
      const char* suffix = kind == CacheEntryKind::MESHES ? ".meshes.tvc" : kind == CacheEntryKind::TENSORS ? ".tensors.tvc"
                         : kind == CacheEntryKind::PAIR ? ".pair.tvc" : kind == CacheEntryKind::RUN ? ".run.tvc"
                         : kind == CacheEntryKind::VOLUME ? ".volume.tvc" : kind == CacheEntryKind::SENSOR ? ".sensor.tvc"
                         : ".scores.tvc";
      return (std::filesystem::path (dir_) / (view_id + suffix)).string ();
    }

    void
    TensorViewCache::saveView (const std::string& view_id, const TensorViewCacheKey& key,
                               const pcl::registration::TensorView& view) const
    {
      if (!view.scan || !view.scan->fine.cloud || !view.scan->reduced.cloud)
        PCL_TENSOR_THROW (pcl::BadArgumentException, "view '" << view_id << "' has no meshes to cache");
      const Eigen::Vector3d extents = principalExtents (*view.scan->fine.cloud);
      writeFileAtomically (entryPath (view_id, CacheEntryKind::MESHES),
                           detail::encodeCacheEntry (CacheEntryKind::MESHES, key, detail::encodeViewPayload (view, extents)));
    }

    CacheEntryState
    TensorViewCache::loadView (const std::string& view_id, const TensorViewCacheKey& key,
                               pcl::registration::TensorView& out) const
    {
      auto entry = detail::readCacheEntry (entryPath (view_id, CacheEntryKind::MESHES), CacheEntryKind::MESHES, key);
      if (entry.state != CacheEntryState::VALID)
        return entry.state;
      pcl::registration::TensorView view;
      Eigen::Vector3d extents;
      if (!detail::decodeViewPayload (entry.payload, view, extents))
        return CacheEntryState::CORRUPT;
      out = view;
      return CacheEntryState::VALID;
    }

    CacheEntryState
    TensorViewCache::loadExtents (const std::string& view_id, const TensorViewCacheKey& key, Eigen::Vector3d& extents) const
    {
      const auto entry = detail::readCacheEntry (entryPath (view_id, CacheEntryKind::MESHES), CacheEntryKind::MESHES, key,
                                                 detail::VIEW_PAYLOAD_HEAD_SIZE);
      if (entry.state != CacheEntryState::VALID)
        return entry.state;
      Eigen::Vector3d origin, read;
      if (!detail::decodeViewHead (entry.payload, origin, read))
        return CacheEntryState::CORRUPT;
      extents = read;
      return CacheEntryState::VALID;
    }

    void
    TensorViewCache::saveTensors (const std::string& view_id, const TensorViewCacheKey& key, const ObjectDimensions& dims,
                                  std::uint64_t tensor_hash, const pcl::PointCloud<pcl::TensorDescriptor>& tensors) const
    {
      writeFileAtomically (entryPath (view_id, CacheEntryKind::TENSORS),
                           detail::encodeCacheEntry (CacheEntryKind::TENSORS, key,
                                                     detail::encodeTensorPayload (dims, tensor_hash, tensors)));
    }

    CacheEntryState
    TensorViewCache::loadTensors (const std::string& view_id, const TensorViewCacheKey& key, const ObjectDimensions& dims,
                                  std::uint64_t tensor_hash, pcl::PointCloud<pcl::TensorDescriptor>::Ptr& out) const
    {
      const auto entry = detail::readCacheEntry (entryPath (view_id, CacheEntryKind::TENSORS), CacheEntryKind::TENSORS, key);
      if (entry.state != CacheEntryState::VALID)
        return entry.state;
      ObjectDimensions stored;
      std::uint64_t stored_hash = 0;
      if (!detail::decodeTensorHead (entry.payload, stored, stored_hash))
        return CacheEntryState::CORRUPT;
      if (!sameBits (stored.D, dims.D) || stored_hash != tensor_hash)
        return CacheEntryState::STALE;
      pcl::PointCloud<pcl::TensorDescriptor>::Ptr tensors (new pcl::PointCloud<pcl::TensorDescriptor>);
      if (!detail::decodeTensorPayload (entry.payload, *tensors))
        return CacheEntryState::CORRUPT;
      out = tensors;
      return CacheEntryState::VALID;
    }

    void
    TensorViewCache::savePair (const std::string& model_id, const std::string& scene_id, const TensorViewCacheKey& key,
                               const pcl::registration::TensorRegistrationReport& report) const
    {
      writeFileAtomically (entryPath (model_id + "--" + scene_id, CacheEntryKind::PAIR),
                           detail::encodeCacheEntry (CacheEntryKind::PAIR, key, detail::encodeReportPayload (report)));
    }

    CacheEntryState
    TensorViewCache::loadPair (const std::string& model_id, const std::string& scene_id, const TensorViewCacheKey& key,
                               pcl::registration::TensorRegistrationReport& out) const
    {
      const auto entry = detail::readCacheEntry (entryPath (model_id + "--" + scene_id, CacheEntryKind::PAIR), CacheEntryKind::PAIR, key);
      if (entry.state != CacheEntryState::VALID)
        return entry.state;
      return detail::decodeReportPayload (entry.payload, out) ? CacheEntryState::VALID : CacheEntryState::CORRUPT;
    }
  }
}
