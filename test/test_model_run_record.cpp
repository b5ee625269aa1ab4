/*
 * The key of a recorded pcl_tensor_model run takes every setting the run's outputs depend on, defaults
 * included, so that a run recorded before a default changed is made again, never replayed.
 */
#include "test_utils.h"

#include <pcl/io/model_run_record.h>

#include <functional>

namespace
{
  using pcl::registration::MultiviewRegistrationParams;
  using pcl::VolumetricIntegrationParams;
}

TEST (ModelRunSettings, HashTakesEverySettingOfTheRun)
{
  const MultiviewRegistrationParams registration;
  const VolumetricIntegrationParams integration;
  const std::uint64_t defaults = pcl::io::hashModelRunSettings (registration, integration);
  EXPECT_EQ (defaults, pcl::io::hashModelRunSettings (registration, integration)) << "the same settings, the same hash";

  std::vector<std::uint64_t> hashes{defaults};
  const auto changed = [&] (const std::function<void (MultiviewRegistrationParams&, VolumetricIntegrationParams&)>& edit) {
    MultiviewRegistrationParams r = registration;
    VolumetricIntegrationParams v = integration;
    edit (r, v);
    hashes.push_back (pcl::io::hashModelRunSettings (r, v));
  };
  changed ([] (auto& r, auto&) { r.pairwise.verification.fine_dimension_fraction += 0.05; });
  changed ([] (auto& r, auto&) { r.pairwise.preparation.target_faces += 1; });
  changed ([] (auto& r, auto&) { r.ranking.sample_tensors += 1; });
  changed ([] (auto& r, auto&) { r.global_verification.tolerance += 1.0; });
  changed ([] (auto& r, auto&) { r.global_verification.checked_dimensions = 3; });
  changed ([] (auto& r, auto&) { r.object_dimensions = Eigen::Vector3d (0.2, 0.1, 0.1); });
  changed ([] (auto& r, auto&) { r.search = pcl::registration::ViewSearch::ORDERED; });
  changed ([] (auto& r, auto&) { r.max_failed_pairs += 1; });
  changed ([] (auto& r, auto&) { r.loop = !r.loop; });
  changed ([] (auto& r, auto&) { r.global_registration = !r.global_registration; });
  changed ([] (auto& r, auto&) { r.min_overlap += 0.1; });
  changed ([] (auto& r, auto&) { r.global.max_iterations += 1; });
  changed ([] (auto& r, auto&) { r.global.sample_points += 1; });
  changed ([] (auto&, auto& v) { v.voxel_size_resolutions *= 2.0; });
  changed ([] (auto&, auto& v) { v.truncation_voxels += 1.0; });
  changed ([] (auto&, auto& v) { v.min_component_fraction *= 2.0; });
  for (std::size_t i = 0; i < hashes.size (); ++i)
    for (std::size_t j = i + 1; j < hashes.size (); ++j)
      EXPECT_NE (hashes[i], hashes[j]) << "settings " << i << " and " << j;
}
