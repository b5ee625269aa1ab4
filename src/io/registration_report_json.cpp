/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/registration_report_json.h>

namespace pcl
{
  namespace io
  {
    namespace
    {
      template <typename Matrix> JsonReport
      rowMajor (const Matrix& m)
      {
        JsonReport a = JsonReport::array ();
        for (int i = 0; i < 16; ++i)
          a.push_back (static_cast<double> (m (i / 4, i % 4)));
        return a;
      }

      const char*
      statusOf (bool registered)
      {
        return registered ? "registered" : "not_registered";
      }

      /** Failures per verification stage, by the stage's name (PASSED, index 0, is no failure). */
      JsonReport
      failuresOf (const pcl::registration::TensorRegistrationReport& r)
      {
        JsonReport f = JsonReport::object ();
        for (std::size_t k = 1; k < r.failures.size (); ++k)
          f[pcl::registration::toString (static_cast<pcl::registration::TensorVerificationStage> (k))] = r.failures[k];
        return f;
      }
    }

    JsonReport
    toJson (const Eigen::Matrix4f& m)
    {
      return rowMajor (m);
    }

    JsonReport
    toJson (const Eigen::Matrix4d& m)
    {
      return rowMajor (m);
    }

    JsonReport
    toJson (const pcl::registration::TensorRegistrationReport& r)
    {
      JsonReport j;
      j["status"] = statusOf (r.registered);
      j["transform"] = toJson (r.transform);
      j["hypotheses_tried"] = r.hypotheses_tried;
      j["hypotheses_skipped"] = r.hypotheses_skipped;
      j["hypotheses_refused"] = r.hypotheses_refused;
      j["ambiguity_checks"] = r.ambiguity_checks;
      j["ambiguous"] = r.ambiguous;
      j["matches"] = r.matches;
      j["comparisons"] = r.comparisons;
      j["tensors"] = {{"model", r.model_tensors}, {"scene", r.scene_tensors}};
      j["resolution"] = r.resolution;
      j["dimensions"] = {r.dimensions.D[0], r.dimensions.D[1], r.dimensions.D[2]};
      if (r.ambiguous)
        j["rival_transforms"] = {toJson (r.verification.transform), toJson (r.rival_transform)};
      if (r.registered)
      {
        const auto& m = r.winning_match;
        j["winning_match"] = {{"model_tensor", m.model}, {"scene_tensor", m.scene}, {"correlation", m.correlation},
                              {"overlap_ratio", m.overlap_ratio}, {"n_q", m.n_q}};
        j["icp_fitness"] = r.verification.icp_fitness;
        j["fine_correspondences"] = r.verification.fine_correspondences;
      }
      j["failures"] = failuresOf (r);
      j["timings_ms"] = {{"prepare", r.timings.prepare_ms}, {"tensors", r.timings.tensors_ms},
                         {"matching", r.timings.matching_ms}, {"verification", r.timings.verification_ms},
                         {"registration", r.timings.total_ms}};
      return j;
    }

    JsonReport
    toJson (const pcl::registration::ViewRegistrationStatus& v)
    {
      JsonReport j;
      j["file"] = v.name;
      j["status"] = statusOf (v.registered);
      j["reference"] = v.reference;
      j["component"] = v.component;
      j["pose"] = toJson (Eigen::Matrix4d (v.pose.matrix ()));
      j["pose_kept"] = v.pose_kept;
      j["hypotheses_tried"] = v.pairwise.hypotheses_tried;
      j["references_tried"] = v.references_tried;
      j["globally_refused"] = v.globally_refused;
      j["timings_ms"] = {{"meshing", v.prepare_ms}, {"tensors", v.tensors_ms}, {"pairwise", v.pairwise_ms}};
      if (!v.error.empty ())
        j["error"] = v.error;
      return j;
    }

    JsonReport
    toJson (const pcl::registration::MultiviewRegistrationResult& r)
    {
      JsonReport j;
      JsonReport views = JsonReport::array ();
      for (const auto& v : r.views)
        views.push_back (toJson (v));
      j["views"] = std::move (views);
      j["registered"] = r.registeredCount ();
      j["reference"] = r.reference;
      j["components"] = r.components;
      j["resolution"] = r.resolution;
      j["dimensions"] = {r.dimensions.D[0], r.dimensions.D[1], r.dimensions.D[2]};
      j["global"] = {{"iterations", r.global.iterations}, {"pairs", r.global.pairs},
                     {"rms_before", r.global.rms_before}, {"rms_after", r.global.rms_after}, {"view_pairs", r.pairs}};
      JsonReport attempts = JsonReport::array ();
      for (const auto& a : r.attempts)
        attempts.push_back ({{"views", {a.first, a.second}}, {"score", a.score}, {"registered", a.registered},
                             {"joined", a.joined}, {"full", a.full}, {"excess", a.excess}, {"ms", a.ms}});
      j["candidate_pairs"] = r.candidates.size ();
      j["candidate_pairs_scored"] = r.candidates_scored;
      j["pairs_registered_ahead_unused"] = r.pairs_registered_ahead_unused;
      j["pairs_registered"] = std::move (attempts);
      j["joins"] = r.joins;
      j["timings_ms"] = {{"meshing", r.timings.prepare_ms}, {"tensors", r.timings.tensors_ms},
                         {"ranking", r.timings.ranking_ms}, {"pairwise", r.timings.pairwise_ms}, {"global", r.timings.global_ms},
                         {"registration", r.timings.total_ms}};
      return j;
    }

    JsonReport
    toJson (const pcl::VolumetricIntegrationReport& r)
    {
      return {{"voxel_size", r.voxel_size}, {"voxels", r.voxels}, {"bytes", r.volume_bytes},
              {"views", r.views}, {"views_kept", r.initial_views}, {"components", r.components}, {"removed_components", r.removed_components},
              {"timings_ms", {{"allocate", r.allocate_ms}, {"integrate", r.integrate_ms}, {"extract", r.extract_ms},
                              {"cleanup", r.cleanup_ms}}}};
    }

    std::string
    dumpJson (const JsonReport& report)
    {
      return report.dump (-1, ' ', false, JsonReport::error_handler_t::replace);
    }
  }
}
