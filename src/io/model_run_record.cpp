/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/model_run_record.h>
#include <pcl/io/atomic_file.h>
#include <pcl/io/content_hash.h>
#include <pcl/io/tensor_view_cache_key.h>
#include "byte_codec.h"
#include "cache_entry_file.h"

#include <filesystem>

namespace pcl
{
  namespace io
  {
    namespace
    {
      std::string
      entryId (const TensorViewCacheKey& key)
      {
        return "run-" + toHex (key.source) + toHex (key.preparation);
      }
    }

    TensorViewCacheKey
    modelRunKey (const std::vector<std::string>& view_files, const std::vector<std::string>& settings)
    {
      ContentHash views, options;
      for (const auto& f : view_files)
        views.add (hashBytes (std::filesystem::weakly_canonical (std::filesystem::absolute (f)).string ()))
            .add (hashFileContents (f));
      for (const auto& s : settings)
        options.add (static_cast<std::uint64_t> (s.size ())).update (s);
      return {views.digest (), options.digest ()};
    }

    std::uint64_t
    hashModelRunSettings (const pcl::registration::MultiviewRegistrationParams& r, const pcl::VolumetricIntegrationParams& v)
    {
      static_assert (sizeof (pcl::registration::GlobalVerificationParams) == 16,
                     "a field was added to GlobalVerificationParams: add it to hashModelRunSettings () too");
      static_assert (sizeof (pcl::registration::MultiviewIcpParams) == 56,
                     "a field was added to MultiviewIcpParams: add it to hashModelRunSettings () too");
      static_assert (sizeof (pcl::VolumetricIntegrationParams) == 56,
                     "a field was added to VolumetricIntegrationParams: add it to hashModelRunSettings () too");
      // Raise when a model run answers differently under the same settings.
      constexpr int kModelRunRevision = 2;
      ContentHash hash;
      hash.update ("model run").add (kModelRunRevision);
      const TensorViewCacheKey pair = pairCacheKey ({}, {}, ObjectDimensions (), r.pairwise);
      hash.add (pair.source).add (pair.preparation).add (hashRankingSettings (ObjectDimensions (), r.pairwise, r.ranking));
      const auto& g = r.global_verification;
      hash.add (g.tolerance).add (g.checked_dimensions);
      hash.add (r.object_dimensions[0]).add (r.object_dimensions[1]).add (r.object_dimensions[2]).add (r.search);
      hash.add (r.max_failed_pairs).add (r.first_pass_hypotheses).add (r.second_pass_pairs).add (r.loop);
      hash.add (r.max_references).add (r.keep_best).add (r.global_registration).add (r.min_overlap).add (r.max_overlap_pairs);
      const auto& i = r.global;
      hash.add (i.max_iterations).add (i.max_distance).add (i.sample_points).add (i.max_normal_angle).add (i.skip_boundary);
      hash.add (i.min_rotation).add (i.min_translation);
      hash.add (v.voxel_size).add (v.voxel_size_resolutions).add (v.truncation_voxels).add (v.border_ramp_edges);
      hash.add (v.pixels_per_resolution).add (v.max_memory_bytes).add (v.min_component_fraction);
      return hash.digest ();
    }

    void
    saveModelRun (const TensorViewCache& cache, const TensorViewCacheKey& key, const ModelRunRecord& record)
    {
      detail::ByteWriter w;
      w.putString (record.report);
      w.putString (record.messages);
      w.put<std::int32_t> (record.exit_code);
      w.put<std::uint64_t> (record.outputs.size ());
      for (const auto& [path, hash] : record.outputs)
      {
        w.putString (path);
        w.put<std::uint64_t> (hash);
      }
      writeFileAtomically (cache.entryPath (entryId (key), CacheEntryKind::RUN),
                           detail::encodeCacheEntry (CacheEntryKind::RUN, key, w.bytes ()));
    }

    bool
    loadModelRun (const TensorViewCache& cache, const TensorViewCacheKey& key, ModelRunRecord& record)
    {
      const auto entry = detail::readCacheEntry (cache.entryPath (entryId (key), CacheEntryKind::RUN), CacheEntryKind::RUN, key);
      if (entry.state != CacheEntryState::VALID)
        return false;
      detail::ByteReader r (entry.payload);
      ModelRunRecord read;
      read.report = r.getString ();
      read.messages = r.getString ();
      read.exit_code = r.get<std::int32_t> ();
      const auto count = r.get<std::uint64_t> ();
      if (!r.fits (count, sizeof (std::uint64_t) * 2))
        return false;
      for (std::uint64_t i = 0; i < count; ++i)
      {
        std::string path = r.getString ();
        const auto hash = r.get<std::uint64_t> ();
        read.outputs.emplace_back (std::move (path), hash);
      }
      if (!r.ok () || !r.atEnd ())
        return false;
      for (const auto& [path, hash] : read.outputs)
        if (!std::filesystem::is_regular_file (path) || hashFileContents (path) != hash)
          return false;  // an output was changed or removed: make it again
      record = read;
      return true;
    }
  }
}
