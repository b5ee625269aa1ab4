/*
 * pcl_tensor evaluation: one method over a list of view pairs, one progress line per pair.
 */
#include "pair_runs.h"

#include <pcl/common/time.h>

#include <cstdio>

namespace pcl_tensor_eval
{
  namespace
  {
    void
    printPair (const PairResult& r, const char* count_label, std::size_t count)
    {
      std::printf ("  %-9s <- %-9s overlap %.3f  %-14s rot %8.3f deg  trans %8.2f d_res  %s %5zu %8.0f ms\n",
                   r.model.c_str (), r.scene.c_str (), r.overlap,
                   r.correct ? "correct" : r.registered ? "WRONG" : "not registered", r.rotation_error_deg,
                   r.translation_error_res, count_label, count, r.time_ms);
    }
  }

  namespace
  {
    /** \a evaluate (model view, scene view) on every pair, with its overlap and one line each. */
    template <typename Evaluate> std::vector<PairResult>
    runHypothesisPairs (const EvalViews& views, const std::vector<std::pair<int, int>>& pairs, Evaluate evaluate)
    {
      std::vector<PairResult> results;
      for (const auto& [m, s] : pairs)
      {
        PairResult r = evaluate (views[m], views[s]);
        r.overlap = pairOverlap (views[m], views[s]);
        printPair (r, "hyp", r.hypotheses);
        results.push_back (r);
      }
      return results;
    }
  }

  std::vector<PairResult>
  runTensorPairs (const EvalViews& views, const pcl::ObjectDimensions& dims, const std::vector<std::pair<int, int>>& pairs,
                  const pcl::registration::TensorRegistrationParams& params)
  {
    return runHypothesisPairs (views, pairs, [&] (const EvalView& model, const EvalView& scene) {
      return evaluateTensorPair (model, scene, dims, params);
    });
  }

  std::vector<PairResult>
  runTensorRegistrationPairs (const EvalViews& views, const std::vector<std::pair<int, int>>& pairs,
                              const pcl::registration::TensorRegistrationParams& params)
  {
    return runHypothesisPairs (views, pairs, [&] (const EvalView& model, const EvalView& scene) {
      return evaluateTensorRegistration (model, scene, params);
    });
  }

  std::vector<FpfhView>
  computeFpfhViews (const EvalViews& views, const FpfhBaselineParams& params)
  {
    std::vector<FpfhView> features;
    for (const EvalView& v : views)
    {
      features.push_back (computeFpfhView (*v.cloud, v.viewpoint, v.prepared->resolution, params));
      std::printf ("  %-10s FPFH: %zu points, %.0f ms\n", v.name.c_str (), features.back ().points->size (),
                   features.back ().time_ms);
    }
    return features;
  }

  std::vector<PairResult>
  runFpfhPairs (const EvalViews& views, const std::vector<FpfhView>& features, const std::vector<std::pair<int, int>>& pairs,
                const FpfhBaselineParams& params, const pcl::registration::TensorVerificationParams& icp)
  {
    std::vector<PairResult> results;
    for (const auto& [m, s] : pairs)
    {
      PairResult r;
      const FpfhResult f = registerFpfh (features[m], features[s], pairResolution (views[m], views[s]), params, icp);
      scoreTransform (views[m], views[s], f.registered, f.transform, r);
      r.overlap = pairOverlap (views[m], views[s]);
      r.time_ms = f.sac_ms + f.icp_ms;
      r.matches = f.inliers;
      printPair (r, "inliers", f.inliers);
      results.push_back (r);
    }
    return results;
  }

  std::vector<PairResult>
  runSpinImagePairs (const EvalViews& views, const pcl::ObjectDimensions& dims, const std::vector<std::pair<int, int>>& pairs,
                     const pcl::registration::TensorRegistrationParams& tensor_params, const SpinImageParams& params)
  {
    const double bin_size = params.bin_size_tensor_bins * dims.mean () / 30.0;  // b_s of Eq. 3
    std::vector<SpinImageView> images;
    for (const EvalView& v : views)
      images.push_back (computeSpinImages (v.prepared->reduced, bin_size, params));
    std::vector<PairResult> results;
    for (const auto& [m, s] : pairs)
    {
      pcl::StopWatch watch;
      const SpinImageResult spin = registerSpinImages (views[m], images[m], views[s], images[s], dims, tensor_params, params);
      PairResult r;
      r.time_ms = watch.getTime ();
      scoreTransform (views[m], views[s], spin.registered, spin.transform, r);
      r.overlap = pairOverlap (views[m], views[s]);
      r.hypotheses = spin.hypotheses;
      printPair (r, "spin hyp", spin.hypotheses);
      results.push_back (r);
    }
    return results;
  }
}
