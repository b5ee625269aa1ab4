/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/scan_sensor_cache.h>
#include <pcl/io/atomic_file.h>
#include <pcl/io/content_hash.h>
#include "byte_codec.h"
#include "cache_entry_file.h"

namespace pcl
{
  namespace io
  {
    namespace
    {
      /** Raise when the sensor that loadRangeScan () gives a file changes (e.g. fitPushbroomSensor ()):
        * sensors kept before are then read again from their files. */
      constexpr int kScanSensorRevision = 1;
    }

    TensorViewCacheKey
    scanSensorKey (std::uint64_t source, const std::string& how)
    {
      ContentHash hash;
      hash.update ("scan sensor").add (kScanSensorRevision).add (static_cast<std::uint64_t> (how.size ())).update (how);
      return {source, hash.digest ()};
    }

    void
    saveScanSensor (const TensorViewCache& cache, const std::string& id, const TensorViewCacheKey& key,
                    const ScanViewpoint& viewpoint)
    {
      detail::ByteWriter w;
      w.put (static_cast<std::uint32_t> (viewpoint.model)).putArray (viewpoint.sensor_pose.matrix ().data (), 16);
      writeFileAtomically (cache.entryPath (id, CacheEntryKind::SENSOR), detail::encodeCacheEntry (CacheEntryKind::SENSOR, key, w.bytes ()));
    }

    bool
    loadScanSensor (const TensorViewCache& cache, const std::string& id, const TensorViewCacheKey& key,
                    ScanViewpoint& viewpoint)
    {
      const auto entry = detail::readCacheEntry (cache.entryPath (id, CacheEntryKind::SENSOR), CacheEntryKind::SENSOR, key);
      if (entry.state != CacheEntryState::VALID)
        return false;
      detail::ByteReader r (entry.payload);
      const auto model = r.get<std::uint32_t> ();
      Eigen::Matrix4d pose;
      r.getArray (pose.data (), 16);
      if (!r.ok () || !r.atEnd () || model > static_cast<std::uint32_t> (ScanViewpoint::Model::pushbroom) || !pose.allFinite ())
        return false;
      viewpoint.model = static_cast<ScanViewpoint::Model> (model);
      viewpoint.sensor_pose.matrix () = pose;
      return true;
    }
  }
}
