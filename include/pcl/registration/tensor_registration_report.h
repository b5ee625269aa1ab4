/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/object_dimensions.h>
#include <pcl/registration/tensor_match.h>
#include <pcl/registration/tensor_verification.h>

#include <Eigen/Core>

#include <array>
#include <cstddef>

namespace pcl
{
  namespace registration
  {
    /** \brief What one pairwise registration did: one object for apps, JSON and the bench. */
    struct TensorRegistrationReport
    {
      bool registered = false;
      /** Takes scene (source) points into the model's (target) frame; identity when not registered. */
      Eigen::Matrix4f transform = Eigen::Matrix4f::Identity ();
      std::size_t model_tensors = 0, scene_tensors = 0;
      std::size_t matches = 0;           ///< tensor pairs above t_r and t_c, and those of the second round when it ran (fallback_overlap_threshold)
      std::size_t comparisons = 0;       ///< tensor pairs compared (mu, Eq. 13)
      std::size_t hypotheses_tried = 0;  ///< matches verified until one passed (or all failed)
      std::size_t hypotheses_skipped = 0;  ///< repeats of hypotheses that ICP refuted
      /** Hypotheses that passed local verification but that the caller's HypothesisAcceptor refused
        * (global verification, Section 4.2). */
      std::size_t hypotheses_refused = 0;
      /** Hypotheses verified after one passed, looking for a second pose (ambiguity_checks). */
      std::size_t ambiguity_checks = 0;
      /** Two distinct poses passed verification: not registered (rival_transform is the second). */
      bool ambiguous = false;
      Eigen::Matrix4f rival_transform = Eigen::Matrix4f::Identity ();
      /** The caller's initial guess passed verification and was taken (TensorRegistration::setVerifyGuess). */
      bool guess_accepted = false;
      /** How many hypotheses failed at each stage (index: TensorVerificationStage). */
      std::array<std::size_t, kTensorVerificationStages> failures{};
      TensorMatch winning_match;                ///< valid when registered from a tensor match
      TensorVerificationResult verification;    ///< of the winning hypothesis when registered
      double resolution = 0.0;                  ///< d_res used by verification
      ObjectDimensions dimensions;              ///< D used by verification
      struct Timings
      {
        double prepare_ms = 0.0, tensors_ms = 0.0, matching_ms = 0.0, verification_ms = 0.0, total_ms = 0.0;
      } timings;
    };
  }
}
