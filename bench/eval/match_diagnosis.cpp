/*
 * pcl_tensor evaluation: where the tensor method loses a pair, matching or verification.
 */
#include "match_diagnosis.h"
#include "pair_evaluation.h"

#include <pcl/registration/correspondence_estimation_tensor.h>
#include <pcl/registration/correspondence_rejection_tensor_verification.h>
#include <pcl/registration/registration_error.h>
#include <pcl/registration/tensor_match.h>

#include <fstream>
#include <stdexcept>

namespace pcl_tensor_eval
{
  MatchDiagnosis
  diagnoseMatches (const EvalView& model, const EvalView& scene, const pcl::ObjectDimensions& dims,
                   const pcl::registration::TensorRegistrationParams& params)
  {
    using namespace pcl::registration;
    // The same matching and verification set-up as TensorRegistration.
    CorrespondenceEstimationTensor estimation = tensorMatcher (params);
    estimation.setInputSource (scene.tensors);
    estimation.setInputTarget (model.tensors);
    pcl::Correspondences correspondences;
    estimation.determineCorrespondences (correspondences);
    CorrespondenceRejectorTensorVerification verification;
    setUpVerification (verification, model, scene, dims, params);

    MatchDiagnosis d;
    d.model = model.name;
    d.scene = scene.name;
    d.matches = estimation.getMatches ().size ();
    const double d_res = pairResolution (model, scene);
    const Eigen::Affine3d truth = groundTruth (model, scene);
    long rank = 0;
    for (const TensorMatch& match : estimation.getMatches ())
    {
      const Eigen::Matrix4f hypothesis = transformFromTensorMatch (match, *model.tensors, *scene.tensors);
      const pcl::RegistrationError e = pcl::registrationError (Eigen::Affine3d (hypothesis.cast<double> ()), truth, d_res);
      const bool good = e.rotation_deg <= kGoodHypothesisRotationDeg && e.translation_resolutions <= kGoodHypothesisTranslationResolutions;
      TensorVerificationResult result;
      const bool passed = verification.verify (hypothesis, result);
      if (good)
      {
        ++d.good;
        ++d.good_stage[static_cast<std::size_t> (result.stage)];
        if (d.first_good_rank < 0)
          d.first_good_rank = rank;
      }
      else if (passed)
      {
        // ICP may still have pulled a rough hypothesis in; only a refined result that is wrong counts.
        const pcl::RegistrationError refined =
            pcl::registrationError (Eigen::Affine3d (result.transform.cast<double> ()), truth, d_res);
        d.bad_passed += refined.rotation_deg > kMaxRotationErrorDeg || refined.translation_resolutions > kMaxTranslationErrorResolutions;
      }
      ++rank;
    }
    return d;
  }

  void
  writeDiagnosisCsv (const std::string& path, const std::vector<MatchDiagnosis>& rows)
  {
    std::ofstream out (path);
    if (!out)
      throw std::runtime_error ("cannot write " + path);
    out << "model,scene,overlap,matches,good_hypotheses,first_good_rank,good_passed,good_fail_coarse_dimensions,"
           "good_fail_coarse_overlap,good_fail_fine_overlap,good_fail_fine_dimensions,good_fail_free_space,bad_passed_wrong\n";
    for (const MatchDiagnosis& d : rows)
    {
      out << d.model << ',' << d.scene << ',' << d.overlap << ',' << d.matches << ',' << d.good << ',' << d.first_good_rank;
      for (std::size_t k = 0; k < d.good_stage.size (); ++k)
        out << ',' << d.good_stage[k];
      out << ',' << d.bad_passed << '\n';
    }
  }
}
