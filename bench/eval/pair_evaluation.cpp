/*
 * pcl_tensor evaluation: one registered pair scored against its ground truth (Section 7.1).
 */
#include "pair_evaluation.h"

#include <pcl/common/centroid.h>
#include <pcl/common/io.h>
#include <pcl/common/time.h>

#include <limits>

namespace pcl_tensor_eval
{
  namespace
  {
    /** The finite points of a prepared view's fine mesh, as plain XYZ. */
    pcl::PointCloud<pcl::PointXYZ>
    finePoints (const EvalView& view)
    {
      pcl::PointCloud<pcl::PointXYZ> points;
      pcl::copyPointCloud (*view.prepared->fine.cloud, points);
      return points;
    }
  }

  double
  pairResolution (const EvalView& model, const EvalView& scene)
  {
    return 0.5 * (model.prepared->resolution + scene.prepared->resolution);
  }

  double
  pairOverlap (const EvalView& model, const EvalView& scene)
  {
    // The paper counts corresponding vertices of the meshes M_i within 2 d_res (Eq. 14).
    return pcl::viewOverlap (finePoints (model), model.pose, finePoints (scene), scene.pose,
                             2.0 * pairResolution (model, scene));
  }

  void
  scoreTransform (const EvalView& model, const EvalView& scene, bool registered, const Eigen::Matrix4f& transform,
                  PairResult& result)
  {
    result.model = model.name;
    result.scene = scene.name;
    result.resolution = pairResolution (model, scene);
    result.registered = registered;
    result.correct = false;
    result.correct_at_centroid = false;
    result.rotation_error_deg = result.translation_error_res = result.centroid_error_res =
        std::numeric_limits<double>::quiet_NaN ();
    if (!registered)
      return;
    const Eigen::Affine3d estimate (transform.cast<double> ());
    const pcl::RegistrationError e = pcl::registrationError (estimate, groundTruth (model, scene), result.resolution);
    result.rotation_error_deg = e.rotation_deg;
    result.translation_error_res = e.translation_resolutions;
    result.correct = e.rotation_deg <= kMaxRotationErrorDeg && e.translation_resolutions <= kMaxTranslationErrorResolutions;
    Eigen::Vector4d centroid = Eigen::Vector4d::Zero ();
    pcl::compute3DCentroid (*scene.prepared->fine.cloud, centroid);
    const Eigen::Vector3d c = centroid.head<3> ();
    result.centroid_error_res = (estimate * c - groundTruth (model, scene) * c).norm () / result.resolution;
    result.correct_at_centroid =
        e.rotation_deg <= kMaxRotationErrorDeg && result.centroid_error_res <= kMaxTranslationErrorResolutions;
  }

  namespace
  {
    /** A tensor registration's outcome on a pair, scored, with its counts and time. */
    PairResult
    scoredReport (const EvalView& model, const EvalView& scene, const pcl::registration::TensorRegistrationReport& report,
                  double time_ms)
    {
      PairResult result;
      result.time_ms = time_ms;
      scoreTransform (model, scene, report.registered, report.transform, result);
      result.hypotheses = report.hypotheses_tried;
      result.matches = report.matches;
      result.failures = report.failures;
      return result;
    }
  }

  PairResult
  evaluateTensorPair (const EvalView& model, const EvalView& scene, const pcl::ObjectDimensions& dims,
                      const pcl::registration::TensorRegistrationParams& params,
                      pcl::registration::TensorRegistrationReport* full_report)
  {
    pcl::StopWatch watch;
    // The views prepared once; the scene's tensors batch by batch, as TensorRegistration computes them
    // (its precomputed ones with one batch).
    pcl::registration::TensorRegistration<pcl::PointNormal> registration;
    registration.setParams (params);
    registration.setObjectDimensions (dims);
    registration.setInputTarget (model.prepared->fine.cloud);
    registration.setInputSource (scene.prepared->fine.cloud);
    registration.setTargetView (tensorView (model));
    registration.setSourceView (tensorView (scene, params.scene_tensor_batches == 1));
    pcl::PointCloud<pcl::PointNormal> aligned;
    registration.align (aligned);
    const pcl::registration::TensorRegistrationReport& report = registration.getReport ();
    const PairResult result = scoredReport (model, scene, report, watch.getTime ());
    if (full_report)
      *full_report = report;
    return result;
  }

  pcl::registration::TensorRegistrationReport
  registerRawScans (const pcl::PointCloud<pcl::PointXYZ>::Ptr& model, const pcl::ScanViewpoint& model_viewpoint,
                    const pcl::PointCloud<pcl::PointXYZ>::Ptr& scene, const pcl::ScanViewpoint& scene_viewpoint,
                    const pcl::registration::TensorRegistrationParams& params)
  {
    pcl::registration::TensorRegistration registration;
    registration.setParams (params);
    registration.setInputTarget (model);
    registration.setInputSource (scene);
    registration.setTargetViewpoint (model_viewpoint);
    registration.setSourceViewpoint (scene_viewpoint);
    pcl::PointCloud<pcl::PointXYZ> aligned;
    registration.alignOrThrow (aligned);
    return registration.getReport ();
  }

  PairResult
  evaluateTensorRegistration (const EvalView& model, const EvalView& scene,
                              const pcl::registration::TensorRegistrationParams& params,
                              pcl::registration::TensorRegistrationReport* full_report)
  {
    const auto report = registerRawScans (model.cloud, model.viewpoint, scene.cloud, scene.viewpoint, params);
    if (full_report)
      *full_report = report;
    return scoredReport (model, scene, report, report.timings.total_ms);
  }
}
