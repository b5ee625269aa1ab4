/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/view_pair_results.h>
#include "file_input.h"
#include <pcl/io/atomic_file.h>
#include <pcl/io/tensor_view_cache_key.h>

#include <limits>
#include <sstream>

namespace pcl
{
  namespace io
  {
    namespace
    {
      using pcl::registration::TensorRegistrationReport;
      using pcl::registration::TensorVerificationStage;

      [[noreturn]] void
      throwBadField (const std::string& key, const char* expected)
      {
        PCL_TENSOR_THROW (pcl::IOException, "\"" << key << "\" must be " << expected);
      }

      const JsonReport&
      field (const JsonReport& j, const std::string& key)
      {
        const auto it = j.find (key);
        if (it == j.end ())
          PCL_TENSOR_THROW (pcl::IOException, "no \"" << key << "\"");
        return *it;
      }

      std::size_t
      count (const JsonReport& j, const std::string& key)
      {
        const JsonReport& v = field (j, key);
        if (!v.is_number_unsigned ())
          throwBadField (key, "a count");
        return v.get<std::size_t> ();
      }

      /** A number; null is NaN, which is how JSON writes it. */
      double
      number (const JsonReport& j, const std::string& key)
      {
        const JsonReport& v = field (j, key);
        if (v.is_null ())
          return std::numeric_limits<double>::quiet_NaN ();
        if (!v.is_number ())
          throwBadField (key, "a number");
        return v.get<double> ();
      }

      bool
      boolean (const JsonReport& j, const std::string& key)
      {
        const JsonReport& v = field (j, key);
        if (!v.is_boolean ())
          throwBadField (key, "true or false");
        return v.get<bool> ();
      }

      std::string
      text (const JsonReport& j, const std::string& key)
      {
        const JsonReport& v = field (j, key);
        if (!v.is_string ())
          throwBadField (key, "a string");
        return v.get<std::string> ();
      }

      /** 16 numbers, row-major; each double read back is the float that was written. */
      Eigen::Matrix4f
      matrix (const JsonReport& v, const std::string& key)
      {
        if (!v.is_array () || v.size () != 16)
          throwBadField (key, "16 numbers");
        Eigen::Matrix4f m;
        for (int i = 0; i < 16; ++i)
        {
          if (!v[i].is_number ())
            throwBadField (key, "16 numbers");
          m (i / 4, i % 4) = static_cast<float> (v[i].get<double> ());
        }
        return m;
      }

      /** The failures per stage, by the stage names toString() gives. */
      void
      readFailures (const JsonReport& j, TensorRegistrationReport& r)
      {
        if (!j.is_object ())
          throwBadField ("failures", "an object");
        for (auto it = j.begin (); it != j.end (); ++it)
        {
          std::size_t k = 1;
          while (k < r.failures.size () && pcl::registration::toString (static_cast<TensorVerificationStage> (k)) != it.key ())
            ++k;
          if (k == r.failures.size ())
            PCL_TENSOR_THROW (pcl::IOException, "\"failures\" names no verification stage \"" << it.key () << "\"");
          r.failures[k] = count (j, it.key ());
        }
      }

      void
      readWinningMatch (const JsonReport& j, TensorRegistrationReport& r)
      {
        const JsonReport& m = field (j, "winning_match");
        r.winning_match.model = static_cast<int> (count (m, "model_tensor"));
        r.winning_match.scene = static_cast<int> (count (m, "scene_tensor"));
        r.winning_match.correlation = static_cast<float> (number (m, "correlation"));
        r.winning_match.overlap_ratio = static_cast<float> (number (m, "overlap_ratio"));
        r.winning_match.n_q = static_cast<int> (count (m, "n_q"));
      }

      void
      readTimings (const JsonReport& j, TensorRegistrationReport& r)
      {
        const JsonReport& t = field (j, "timings_ms");
        r.timings.prepare_ms = number (t, "prepare");
        r.timings.tensors_ms = number (t, "tensors");
        r.timings.matching_ms = number (t, "matching");
        r.timings.verification_ms = number (t, "verification");
        r.timings.total_ms = number (t, "registration");
      }

      /** One line of a results file. */
      ViewPairResult
      parseResult (const std::string& line)
      {
        const JsonReport j = JsonReport::parse (line, nullptr, false);
        if (j.is_discarded () || !j.is_object ())
          PCL_TENSOR_THROW (pcl::IOException, "not a JSON object");
        ViewPairResult result;
        result.model = text (j, "model_id");
        result.scene = text (j, "scene_id");
        if (!isValidViewId (result.model) || !isValidViewId (result.scene))
          PCL_TENSOR_THROW (pcl::IOException, "\"model_id\" and \"scene_id\" must be view ids (viewIdOf)");
        result.model_file = text (j, "model_file");
        result.scene_file = text (j, "scene_file");
        result.report = registrationReportFromJson (field (j, "report"));
        return result;
      }
    }

    ViewPairResult
    makeViewPairResult (const std::string& model_file, const std::string& scene_file, const TensorRegistrationReport& report)
    {
      ViewPairResult result;
      result.model = viewIdOf (model_file);
      result.scene = viewIdOf (scene_file);
      result.model_file = model_file;
      result.scene_file = scene_file;
      result.report = report;
      return result;
    }

    JsonReport
    toJson (const ViewPairResult& result)
    {
      JsonReport j;
      j["model_file"] = result.model_file;
      j["model_id"] = result.model;
      j["scene_file"] = result.scene_file;
      j["scene_id"] = result.scene;
      j["report"] = toJson (result.report);
      return j;
    }

    TensorRegistrationReport
    registrationReportFromJson (const JsonReport& j)
    {
      if (!j.is_object ())
        PCL_TENSOR_THROW (pcl::IOException, "\"report\" must be an object");
      TensorRegistrationReport r;
      const std::string status = text (j, "status");
      if (status != "registered" && status != "not_registered")
        throwBadField ("status", "\"registered\" or \"not_registered\"");
      r.registered = status == "registered";
      r.transform = matrix (field (j, "transform"), "transform");
      r.hypotheses_tried = count (j, "hypotheses_tried");
      r.hypotheses_skipped = count (j, "hypotheses_skipped");
      r.hypotheses_refused = count (j, "hypotheses_refused");
      r.ambiguity_checks = count (j, "ambiguity_checks");
      r.ambiguous = boolean (j, "ambiguous");
      r.matches = count (j, "matches");
      r.comparisons = count (j, "comparisons");
      r.model_tensors = count (field (j, "tensors"), "model");
      r.scene_tensors = count (field (j, "tensors"), "scene");
      r.resolution = number (j, "resolution");
      const JsonReport& d = field (j, "dimensions");
      if (!d.is_array () || d.size () != 3 || !d[0].is_number () || !d[1].is_number () || !d[2].is_number ())
        throwBadField ("dimensions", "3 numbers");
      r.dimensions.D = Eigen::Vector3d (d[0].get<double> (), d[1].get<double> (), d[2].get<double> ());
      if (r.ambiguous)
      {
        const JsonReport& rivals = field (j, "rival_transforms");
        if (!rivals.is_array () || rivals.size () != 2)
          throwBadField ("rival_transforms", "two transforms");
        r.verification.transform = matrix (rivals[0], "rival_transforms");
        r.rival_transform = matrix (rivals[1], "rival_transforms");
      }
      if (r.registered)
      {
        readWinningMatch (j, r);
        r.verification.stage = TensorVerificationStage::PASSED;
        r.verification.transform = r.transform;
        r.verification.icp_fitness = number (j, "icp_fitness");
        r.verification.fine_correspondences = number (j, "fine_correspondences");
      }
      readFailures (field (j, "failures"), r);
      readTimings (j, r);
      return r;
    }

    std::string
    formatViewPairResults (const std::vector<ViewPairResult>& results)
    {
      std::string lines;
      for (const auto& result : results)
        lines += dumpJson (toJson (result)) + "\n";
      return lines;
    }

    void
    saveViewPairResults (const std::string& path, const std::vector<ViewPairResult>& results)
    {
      writeFileAtomically (path, formatViewPairResults (results));
    }

    std::vector<ViewPairResult>
    loadViewPairResults (const std::string& path)
    {
      std::istringstream file (detail::readFile (path));
      std::vector<ViewPairResult> results;
      std::string line;
      for (int line_no = 1; std::getline (file, line); ++line_no)
      {
        if (line.find_first_not_of (" \t\r") == std::string::npos)
          continue;
        try
        {
          results.push_back (parseResult (line));
        }
        catch (const pcl::IOException& e)
        {
          detail::throwAtLine (path, line_no, pcl::errorDescription (e));
        }
      }
      return results;
    }

    TensorRegistrationReport
    reportWithinHypotheses (const TensorRegistrationReport& report, int max_hypotheses)
    {
      if (max_hypotheses <= 0 || report.hypotheses_tried <= static_cast<std::size_t> (max_hypotheses))
        return report;
      TensorRegistrationReport capped = report;
      capped.registered = false;
      capped.ambiguous = false;
      capped.transform = Eigen::Matrix4f::Identity ();
      capped.rival_transform = Eigen::Matrix4f::Identity ();
      capped.winning_match = {};
      capped.verification = {};
      capped.hypotheses_tried = static_cast<std::size_t> (max_hypotheses);
      return capped;
    }
  }
}
