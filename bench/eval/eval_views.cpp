/*
 * pcl_tensor evaluation: views of one object with ground-truth poses, prepared once for all pairs.
 */
#include "eval_views.h"
// The pipeline's own set-up of its matcher and verifier (private to the library), not a copy of it.
#include "registration/tensor_configuration.h"

#include <pcl/common/time.h>
#include <pcl/io/range_scan_io.h>
#include <pcl/io/stanford_conf.h>
#include <pcl/simulation/view_set.h>

#include <cstdio>

namespace pcl_tensor_eval
{
  EvalViews
  loadStanfordViews (const std::string& conf_path)
  {
    const std::string dir = conf_path.substr (0, conf_path.find_last_of ('/') + 1);
    EvalViews views;
    for (const auto& entry : pcl::io::loadStanfordConf (conf_path))
    {
      pcl::io::RangeScan scan = pcl::io::loadRangeScan (dir + entry.file);
      EvalView v;
      v.name = entry.file.substr (0, entry.file.find_last_of ('.'));
      v.cloud = scan.cloud;
      v.viewpoint = scan.viewpoint;
      v.pose = entry.pose ();
      v.finite_points = scan.finite_points;
      views.push_back (v);
    }
    return views;
  }

  EvalViews
  makeSyntheticViews (const pcl::ScanMesh& mesh, const pcl::SyntheticViewParams& params)
  {
    return makeSyntheticViews (mesh, params, pcl::makeDefaultViewDirections (params.up));
  }

  EvalViews
  makeSyntheticViews (const pcl::ScanMesh& mesh, const pcl::SyntheticViewParams& params, const pcl::ViewDirections& directions)
  {
    EvalViews views;
    const auto rendered = pcl::renderSyntheticViews (mesh, directions, params);
    for (std::size_t i = 0; i < rendered.size (); ++i)
    {
      EvalView v;
      v.name = "view" + std::to_string (i);
      v.cloud = rendered[i].view.cloud;
      v.viewpoint = rendered[i].view.viewpoint;
      v.pose = rendered[i].view.pose;
      v.finite_points = pcl::io::updateDenseFlag (*v.cloud);
      views.push_back (v);
    }
    return views;
  }

  pcl::ObjectDimensions
  prepareViews (EvalViews& views, const pcl::registration::TensorRegistrationParams& params)
  {
    std::vector<const pcl::PointCloud<pcl::PointNormal>*> fine;
    for (EvalView& v : views)
    {
      pcl::StopWatch watch;
      v.prepared = std::make_shared<const pcl::PreparedScan> (pcl::prepareScan (*v.cloud, v.viewpoint, params.preparation));
      v.prepare_ms = watch.getTime ();
      fine.push_back (v.prepared->fine.cloud.get ());
    }
    // D must come from all views: the two views of a pair alone underestimate the object (Eq. 1).
    const pcl::ObjectDimensions dims = pcl::computeObjectDimensions<pcl::PointNormal> (fine);
    for (EvalView& v : views)
    {
      pcl::StopWatch watch;
      v.tensors = pcl::registration::computeViewTensors (*v.prepared, dims, params);
      v.tensors_ms = watch.getTime ();
    }
    return dims;
  }

  pcl::registration::TensorView::Ptr
  tensorView (const EvalView& view, bool tensors)
  {
    auto v = std::make_shared<pcl::registration::TensorView> ();
    v->scan = view.prepared;
    if (tensors)
      v->tensors = view.tensors;
    return v;
  }

  pcl::registration::CorrespondenceEstimationTensor
  tensorMatcher (const pcl::registration::TensorRegistrationParams& params)
  {
    pcl::registration::CorrespondenceEstimationTensor matcher;
    pcl::registration::detail::configureMatcher (matcher, params);
    return matcher;
  }

  void
  setUpVerification (pcl::registration::CorrespondenceRejectorTensorVerification& verification, const EvalView& model,
                     const EvalView& scene, const pcl::ObjectDimensions& dims,
                     const pcl::registration::TensorRegistrationParams& params)
  {
    pcl::registration::detail::configureVerifier (verification, *tensorView (model), scene.tensors, *tensorView (scene),
                                                  dims, params);
  }

  void
  printViews (const EvalViews& views, const pcl::ObjectDimensions& dims)
  {
    std::printf ("D = [%.4f %.4f %.4f]\n", dims.D[0], dims.D[1], dims.D[2]);
    for (const EvalView& v : views)
      std::printf ("  %-10s %6zu points, d_res %.6f, %4zu tensors, prepare %.0f ms, tensors %.0f ms\n", v.name.c_str (),
                   v.finite_points, v.prepared->resolution, v.tensors->size (), v.prepare_ms, v.tensors_ms);
  }

  std::vector<std::pair<int, int>>
  allPairs (int n)
  {
    std::vector<std::pair<int, int>> pairs;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        pairs.emplace_back (i, j);
    return pairs;
  }
}
