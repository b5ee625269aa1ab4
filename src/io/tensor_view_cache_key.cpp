/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/tensor_view_cache_key.h>
#include <pcl/io/content_hash.h>

#include <algorithm>
#include <filesystem>
#include <utility>

namespace pcl
{
  namespace io
  {
    namespace
    {
      bool
      isIdCharacter (char c)
      {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
               c == '.';
      }

      /** Each hash starts with what it is of, so that equal bytes of two kinds never give one key. */
      ContentHash
      taggedHash (std::string_view tag)
      {
        ContentHash hash;
        hash.add (static_cast<std::uint64_t> (tag.size ())).update (tag);
        return hash;
      }
    }

    std::uint64_t
    hashPointCloud (const pcl::PointCloud<pcl::PointXYZ>& cloud)
    {
      ContentHash hash = taggedHash ("range image");
      hash.add (cloud.width).add (cloud.height).add (static_cast<std::uint64_t> (cloud.size ()));
      for (const auto& p : cloud)
        hash.add (p.x).add (p.y).add (p.z);
      return hash.digest ();
    }

    // A new field of ScanPreparationParams changes its size on this ABI: hash it below, then update this.
    static_assert (sizeof (ScanPreparationParams) == 64, "hash every field of ScanPreparationParams in hashPreparation");

    std::uint64_t
    hashPreparation (const ScanPreparationParams& params, const ScanViewpoint& viewpoint)
    {
      ContentHash hash = taggedHash ("preparation");
      hash.add (params.edge_std_devs).add (params.target_faces).add (params.normal_method)
          .add (params.normal_radius_resolutions).add (params.stray_fragment_gap).add (params.stray_fragment_fraction)
          .add (params.speck_max_pixels).add (params.speck_jump).add (params.reduction_grid_step);
      hash.add (viewpoint.model);
      const Eigen::Matrix4d& pose = viewpoint.sensor_pose.matrix ();
      for (Eigen::Index i = 0; i < pose.size (); ++i)
        hash.add (pose.data ()[i]);
      return hash.digest ();
    }

    std::uint64_t
    hashTensorParameters (const pcl::registration::TensorRegistrationParams& params)
    {
      // The fields detail::configureEstimation() sets (src/registration/tensor_configuration.cpp).
      ContentHash hash = taggedHash ("tensors");
      hash.add (params.grid_size).add (params.partners_per_vertex).add (params.min_normal_angle)
          .add (params.region_growing);
      return hash.digest ();
    }

    namespace
    {
      /** Cached pair results of an older verification are stale even under the same parameters: raise
        * this when verification changes its verdicts (2: the free-space check's occlusion and noise rules;
        * 3: rival turns along the screw of the least constrained motion; 4: a rival probe's ICP ends where
        * a stage is short of pairs; 5: rivals that only the other sensor's background speaks against are dismissed;
        * 6: rivals are held to D more loosely; 7: ICP pairs compatible normals only). */
      constexpr int kVerificationRevision = 7;
    }

    TensorViewCacheKey
    pairCacheKey (const TensorViewCacheKey& model, const TensorViewCacheKey& scene, const ObjectDimensions& dims,
                  const pcl::registration::TensorRegistrationParams& params)
    {
      static_assert (sizeof (pcl::registration::TensorVerificationParams) == 128,
                     "a field was added to TensorVerificationParams: add it to pairCacheKey () too");
      static_assert (sizeof (pcl::registration::TensorRegistrationParams) == 344,
                     "a field was added to TensorRegistrationParams: add it to pairCacheKey () too");
      TensorViewCacheKey key;
      key.source = taggedHash ("pair").add (model.source).add (model.preparation).add (scene.source).add (scene.preparation).digest ();
      const auto& v = params.verification;
      ContentHash hash = taggedHash ("registration");
      hash.add (kVerificationRevision).add (dims.D[0]).add (dims.D[1]).add (dims.D[2]).add (hashTensorParameters (params));
      hash.add (hashPreparation (params.preparation, ScanViewpoint ()));
      hash.add (params.overlap_threshold).add (params.correlation_threshold).add (params.fallback_overlap_threshold)
          .add (params.fallback_correlation_threshold).add (params.theta_bin_width).add (static_cast<int> (params.order))
          .add (params.scene_tensor_batches).add (params.batch_hypotheses)
          .add (params.max_hypotheses).add (params.repeat_rotation).add (params.repeat_translation)
          .add (params.ambiguity_checks).add (params.ambiguity_rotation).add (params.probe_rivals).add (params.rival_margin)
          .add (params.rival_empty_space_margin).add (params.rival_empty_space_fraction).add (params.rival_dimension_factor)
          .add (params.rival_icp_max_normal_angle);
      hash.add (v.coarse_dimension_fraction).add (v.correspondence_fraction).add (v.coarse_distance).add (v.count_both_views)
          .add (v.fine_distance).add (v.fine_dimension_tolerance).add (v.fine_dimension_fraction).add (v.checked_dimensions).add (v.icp_iterations)
          .add (v.icp_max_distance).add (v.icp_final_distance).add (v.icp_coarse_stage_step).add (v.icp_max_normal_angle).add (v.sample_points)
          .add (v.free_space_distance).add (v.free_space_fraction).add (v.empty_space_margin);
      key.preparation = hash.digest ();
      return key;
    }

    std::uint64_t
    hashRankingSettings (const ObjectDimensions& dims, const pcl::registration::TensorRegistrationParams& params,
                         const pcl::registration::ViewPairRankingParams& ranking)
    {
      static_assert (sizeof (pcl::registration::ViewPairRankingParams) == 24,
                     "a field was added to ViewPairRankingParams: add it to hashRankingSettings () too");
      // Raise when ViewPairRanking scores differently under the same settings.
      constexpr int kRankingRevision = 1;
      ContentHash hash = taggedHash ("ranking");
      hash.add (kRankingRevision).add (dims.D[0]).add (dims.D[1]).add (dims.D[2]).add (hashTensorParameters (params));
      hash.add (params.overlap_threshold).add (params.correlation_threshold).add (params.theta_bin_width);
      hash.add (ranking.sample_tensors).add (ranking.agreement_degrees).add (ranking.agreement_distance);
      return hash.digest ();
    }

    TensorViewCacheKey
    pairScoreKey (const TensorViewCacheKey& a, const TensorViewCacheKey& b, std::uint64_t ranking_settings)
    {
      const bool in_order = std::make_pair (a.source, a.preparation) < std::make_pair (b.source, b.preparation);
      const TensorViewCacheKey& first = in_order ? a : b;
      const TensorViewCacheKey& second = in_order ? b : a;
      ContentHash pair = taggedHash ("pair score");
      pair.add (first.source).add (first.preparation).add (second.source).add (second.preparation);
      return {pair.digest (), ranking_settings};
    }

    std::string
    viewIdOf (const std::string& path)
    {
      namespace fs = std::filesystem;
      std::error_code ec;
      // weakly_canonical: the file need not exist (yet), and "a/../b.ply" and "b.ply" are one view.
      fs::path canonical = fs::weakly_canonical (fs::absolute (path), ec);
      if (ec)
        canonical = fs::absolute (path).lexically_normal ();
      std::string stem = fs::path (path).stem ().string ();
      std::replace_if (stem.begin (), stem.end (), [] (char c) { return !isIdCharacter (c); }, '_');
      if (stem.empty () || stem[0] == '.')
        stem.insert (stem.begin (), '_');
      stem.resize (std::min<std::size_t> (stem.size (), 64));
      return stem + "-" + toHex (hashBytes (canonical.string ()));
    }

    bool
    isValidViewId (const std::string& view_id)
    {
      return !view_id.empty () && view_id.size () <= 200 && view_id[0] != '.' &&
             std::all_of (view_id.begin (), view_id.end (), isIdCharacter);
    }
  }
}
