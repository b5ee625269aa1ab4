/*
 * pcl_tensor evaluation: where the tensor method loses a pair, matching or verification.
 */
#pragma once

#include "eval_views.h"

#include <array>
#include <string>
#include <vector>

namespace pcl_tensor_eval
{
  /** \brief A hypothesis of one tensor match is "good" when ICP could finish it: within twice the
    * correctness bounds of the ground truth (10 degrees, 40 d_res).
    */
  constexpr double kGoodHypothesisRotationDeg = 10.0;
  constexpr double kGoodHypothesisTranslationResolutions = 40.0;

  /** \brief How many matches of a pair give a good hypothesis, and what verification made of them. */
  struct MatchDiagnosis
  {
    std::string model, scene;
    double overlap = 0.0;
    std::size_t matches = 0;
    std::size_t good = 0;                 ///< matches whose hypothesis is good
    long first_good_rank = -1;            ///< 0-based position of the first good one in the verification order
    std::array<std::size_t, pcl::registration::kTensorVerificationStages> good_stage{};  ///< the good ones, by verification stage reached (0: passed)
    std::size_t bad_passed = 0;           ///< matches with a bad hypothesis that passed verification (wrong answers)
  };

  /** \brief Match the pair as TensorRegistration does, then score and verify every match's hypothesis. */
  MatchDiagnosis
  diagnoseMatches (const EvalView& model, const EvalView& scene, const pcl::ObjectDimensions& dims,
                   const pcl::registration::TensorRegistrationParams& params);

  /** \brief One CSV row per pair. \throw std::runtime_error when the file cannot be written */
  void
  writeDiagnosisCsv (const std::string& path, const std::vector<MatchDiagnosis>& rows);
}
