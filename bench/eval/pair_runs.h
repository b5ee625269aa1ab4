/*
 * pcl_tensor evaluation: one method over a list of view pairs, one progress line per pair.
 */
#pragma once

#include "eval_views.h"
#include "fpfh_baseline.h"
#include "pair_evaluation.h"
#include "spin_image_baseline.h"

#include <utility>
#include <vector>

namespace pcl_tensor_eval
{
  /** \brief Register every pair (model, scene) with the tensor method and score it, overlap included. */
  std::vector<PairResult>
  runTensorPairs (const EvalViews& views, const pcl::ObjectDimensions& dims, const std::vector<std::pair<int, int>>& pairs,
                  const pcl::registration::TensorRegistrationParams& params);

  /** \brief Every pair registered as pcl_tensor_register does (evaluateTensorRegistration(): the raw
    * scans, D from each pair alone); time_ms is the registration after loading. */
  std::vector<PairResult>
  runTensorRegistrationPairs (const EvalViews& views, const std::vector<std::pair<int, int>>& pairs,
                              const pcl::registration::TensorRegistrationParams& params);

  /** \brief The FPFH baseline of every view, computed once (as the tensors are). */
  std::vector<FpfhView>
  computeFpfhViews (const EvalViews& views, const FpfhBaselineParams& params);

  /** \brief The FPFH baseline on every pair, from the features of computeFpfhViews(); time_ms is SAC + ICP. */
  std::vector<PairResult>
  runFpfhPairs (const EvalViews& views, const std::vector<FpfhView>& features, const std::vector<std::pair<int, int>>& pairs,
                const FpfhBaselineParams& params, const pcl::registration::TensorVerificationParams& icp);

  /** \brief Spin images of every view's reduced mesh (bin size from D, as the tensors'), then
    * registerSpinImages() on every pair; time_ms is matching and verification. */
  std::vector<PairResult>
  runSpinImagePairs (const EvalViews& views, const pcl::ObjectDimensions& dims, const std::vector<std::pair<int, int>>& pairs,
                     const pcl::registration::TensorRegistrationParams& tensor_params, const SpinImageParams& params);
}
