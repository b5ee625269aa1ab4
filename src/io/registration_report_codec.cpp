/*
 * pcl_tensor: a pairwise registration report as cache bytes (internal; TensorViewCache's pair entries).
 */
#include "registration_report_codec.h"
#include "byte_codec.h"

namespace pcl
{
  namespace io
  {
    namespace detail
    {
      namespace
      {
        using pcl::registration::TensorRegistrationReport;

        /** Writes or reads every field of a report in one order, so that both directions cannot drift. */
        template <typename Io, typename Report> void
        visitReport (Io& io, Report& r)
        {
          io.flag (r.registered).flag (r.ambiguous).flag (r.guess_accepted);
          io.matrix (r.transform).matrix (r.rival_transform);
          io.size (r.model_tensors).size (r.scene_tensors).size (r.matches).size (r.comparisons);
          io.size (r.hypotheses_tried).size (r.hypotheses_skipped).size (r.hypotheses_refused).size (r.ambiguity_checks);
          for (auto& f : r.failures)
            io.size (f);
          io.number (r.winning_match.model).number (r.winning_match.scene).flag (r.winning_match.scene_flipped);
          io.number (r.winning_match.correlation).number (r.winning_match.overlap_ratio).number (r.winning_match.n_q);
          auto& v = r.verification;
          io.stage (v.stage).matrix (v.transform);
          io.number (v.coarse_dimension_excess).number (v.coarse_correspondences).number (v.required_correspondences);
          io.number (v.fine_correspondences).number (v.fine_dimension_excess).number (v.icp_fitness).number (v.free_space_violation);
          io.number (r.resolution).number (r.dimensions.D[0]).number (r.dimensions.D[1]).number (r.dimensions.D[2]);
          io.number (r.timings.prepare_ms).number (r.timings.tensors_ms).number (r.timings.matching_ms);
          io.number (r.timings.verification_ms).number (r.timings.total_ms);
        }

        struct Encoder
        {
          ByteWriter out;
          template <typename T> Encoder& number (const T& v) { out.put (v); return *this; }
          Encoder& flag (bool v) { out.put<std::uint8_t> (v ? 1 : 0); return *this; }
          Encoder& size (std::size_t v) { out.put<std::uint64_t> (v); return *this; }
          Encoder& stage (pcl::registration::TensorVerificationStage s) { out.put<std::uint32_t> (static_cast<std::uint32_t> (s)); return *this; }
          Encoder&
          matrix (const Eigen::Matrix4f& m)
          {
            for (int k = 0; k < 16; ++k)
              out.put (m.data ()[k]);
            return *this;
          }
        };

        struct Decoder
        {
          ByteReader in;
          bool ok = true;
          template <typename T> Decoder& number (T& v) { v = in.get<T> (); return *this; }
          Decoder&
          flag (bool& v)
          {
            const auto b = in.get<std::uint8_t> ();
            ok = ok && b <= 1;
            v = b == 1;
            return *this;
          }
          Decoder& size (std::size_t& v) { v = static_cast<std::size_t> (in.get<std::uint64_t> ()); return *this; }
          Decoder&
          stage (pcl::registration::TensorVerificationStage& s)
          {
            const auto value = in.get<std::uint32_t> ();
            ok = ok && value < pcl::registration::kTensorVerificationStages;
            s = static_cast<pcl::registration::TensorVerificationStage> (value);
            return *this;
          }
          Decoder&
          matrix (Eigen::Matrix4f& m)
          {
            for (int k = 0; k < 16; ++k)
              m.data ()[k] = in.get<float> ();
            return *this;
          }
        };
      }

      std::string
      encodeReportPayload (const TensorRegistrationReport& report)
      {
        Encoder e;
        TensorRegistrationReport copy = report;
        visitReport (e, copy);
        return e.out.bytes ();
      }

      bool
      decodeReportPayload (std::string_view payload, TensorRegistrationReport& report)
      {
        Decoder d{ByteReader (payload)};
        TensorRegistrationReport read;
        visitReport (d, read);
        if (!d.ok || !d.in.ok () || !d.in.atEnd ())
          return false;
        report = read;
        return true;
      }
    }
  }
}
