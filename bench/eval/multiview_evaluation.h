/*
 * pcl_tensor evaluation: multiview registration scored against ground-truth poses (issue 6).
 */
#pragma once

#include "eval_views.h"

#include <pcl/registration/multiview_tensor_registration.h>

#include <string>
#include <vector>

namespace pcl_tensor_eval
{
  /** \brief Errors of one view's estimated pose (Eq. 11, Eq. 12) after aligning the estimated frame
    * to the ground truth by the reference view's pose; NaN when the view is not registered. */
  struct ViewPoseError
  {
    double rotation_deg = 0.0;
    double translation_res = 0.0;
  };

  /** \brief Max and median of the errors of the registered views. */
  struct PoseErrorSummary
  {
    std::size_t views = 0;
    double max_rotation_deg = 0.0, median_rotation_deg = 0.0;
    double max_translation_res = 0.0, median_translation_res = 0.0;
  };

  /** \brief The estimated poses of \a views (common frame = the reference view's) against the ground
    * truth: pose error of GT(reference) * estimate(i) against GT(i), in units of \a resolution.
    * \param[in] registered which views have an estimate */
  std::vector<ViewPoseError>
  poseErrors (const EvalViews& views, const pcl::registration::ViewPoses& estimates, const std::vector<bool>& registered,
              int reference, double resolution);

  /** \brief The same errors after the common frame that fits the estimates best to the ground truth
    * (pcl::bestFitCommonFrame over each registered view's points) instead of the reference view's pose. */
  std::vector<ViewPoseError>
  poseErrorsInBestFrame (const EvalViews& views, const pcl::registration::ViewPoses& estimates,
                         const std::vector<bool>& registered, double resolution);

  PoseErrorSummary
  summarize (const std::vector<ViewPoseError>& errors);

  /** \brief The views as multiview registration's input. */
  std::vector<pcl::registration::MultiviewInput>
  multiviewInputs (const EvalViews& views);

  /** \brief The alternative global step: PCL's pcl::registration::LUM (Lu and Milios, 6-DoF form of
    * Borrmann et al.) over the same pairs, from the pairwise poses, with point-to-point
    * correspondences re-found from the current poses before each of \a rounds LUM runs.
    * \return the poses (reference view fixed) */
  pcl::registration::ViewPoses
  lumGlobalRegistration (const pcl::registration::MultiviewRegistrationResult& result, int rounds, int sample_points,
                         double max_distance_res);
}
