/*
 * pcl_tensor evaluation: one registered pair scored against its ground truth (Section 7.1).
 */
#pragma once

#include "eval_views.h"

#include <pcl/registration/registration_error.h>

#include <array>
#include <string>

namespace pcl_tensor_eval
{
  /** \brief A registration is correct when both errors are within these bounds (issue 5). */
  constexpr double kMaxRotationErrorDeg = 5.0;
  constexpr double kMaxTranslationErrorResolutions = 20.0;

  /** \brief What one method did on one pair, scored against the ground truth. */
  struct PairResult
  {
    std::string model, scene;
    double overlap = 0.0;     ///< Eq. 14 with the ground-truth poses, within 2 d_res
    double resolution = 0.0;  ///< d_res of the pair: mean of the two fine meshes' resolutions
    bool registered = false;  ///< the method reported a registration
    bool correct = false;     ///< registered, and both errors within the bounds
    /** Errors of the reported transform (Eq. 11 and Eq. 12); NaN when not registered. */
    double rotation_error_deg = 0.0, translation_error_res = 0.0;
    /** How far the scene's centroid lands from where the ground truth puts it, in d_res; NaN when not
      * registered. Unlike Eq. 12 it does not depend on where the view frames' origins are: a synthetic
      * sensor frame's origin is ~0.3 m from the object, so there Eq. 12 grows by ~5 d_res per degree. */
    double centroid_error_res = 0.0;
    /** Registered, rotation error within the bound, and centroid error within the translation bound. */
    bool correct_at_centroid = false;
    std::size_t hypotheses = 0, matches = 0;
    std::array<std::size_t, pcl::registration::kTensorVerificationStages> failures{};  ///< tensor method: failures per verification stage
    double time_ms = 0.0;
    /** A registration was reported, and it is wrong: the one outcome that must never happen. */
    bool wrong () const { return registered && !correct; }
  };

  /** \brief d_res of a pair, as the tensor verification uses it. */
  double
  pairResolution (const EvalView& model, const EvalView& scene);

  /** \brief Overlap of Eq. 14 between two prepared views, from their ground-truth poses. */
  double
  pairOverlap (const EvalView& model, const EvalView& scene);

  /** \brief Fill in registered, correct and the errors of a reported transform (scene -> model). */
  void
  scoreTransform (const EvalView& model, const EvalView& scene, bool registered, const Eigen::Matrix4f& transform,
                  PairResult& result);

  /** \brief Register the scene view to the model view with TensorRegistration on the views prepared once, and score it.
    * \param[out] report when given, the registration's whole report (e.g. the winning match) */
  PairResult
  evaluateTensorPair (const EvalView& model, const EvalView& scene, const pcl::ObjectDimensions& dims,
                      const pcl::registration::TensorRegistrationParams& params,
                      pcl::registration::TensorRegistrationReport* report = nullptr);

  /** \brief What pcl_tensor_register does after loading: pcl::registration::TensorRegistration of the
    * scene's raw cloud to the model's, from their sensors, with D from the two alone.
    */
  pcl::registration::TensorRegistrationReport
  registerRawScans (const pcl::PointCloud<pcl::PointXYZ>::Ptr& model, const pcl::ScanViewpoint& model_viewpoint,
                    const pcl::PointCloud<pcl::PointXYZ>::Ptr& scene, const pcl::ScanViewpoint& scene_viewpoint,
                    const pcl::registration::TensorRegistrationParams& params);

  /** \brief Register the scene's raw scan to the model's as pcl_tensor_register does, and score it:
    * pcl::registration::TensorRegistration from the two clouds and sensors, D from the pair alone.
    * Its time is the registration after loading (TensorRegistrationReport::timings.total_ms).
    * \param[out] report when given, the registration's whole report (e.g. ambiguous, the transform)
    */
  PairResult
  evaluateTensorRegistration (const EvalView& model, const EvalView& scene,
                              const pcl::registration::TensorRegistrationParams& params,
                              pcl::registration::TensorRegistrationReport* report = nullptr);
}
