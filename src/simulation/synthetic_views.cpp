/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/simulation/synthetic_views.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/simulation/range_noise.h>
#include <pcl/surface/range_scan_triangulation.h>

#include <random>

namespace pcl
{
  namespace
  {
    double
    viewResolution (const RenderedView& view)
    {
      RangeScanTriangulation triangulation;
      triangulation.setViewpoint (view.viewpoint);
      ScanMesh mesh;
      triangulation.triangulate (*view.cloud, mesh);
      return meshResolution (mesh);
    }
  }

  std::vector<SyntheticView>
  renderSyntheticViews (const ScanMesh& model, const SensorPoses& poses, const SyntheticViewParams& params)
  {
    if (!(params.noise_sigma_resolutions >= 0.0) || !std::isfinite (params.noise_sigma_resolutions))
      PCL_TENSOR_THROW (pcl::BadArgumentException, "noise sigma must be finite and >= 0 d_res, got "
                        << params.noise_sigma_resolutions);
    ZBufferRangeRenderer renderer;
    renderer.setMesh (model);
    renderer.setCameraParams (params.camera);
    std::mt19937 rng (params.seed), artifact_rng (params.seed ^ 0x5ca1ab1eu);
    std::vector<SyntheticView> views;
    views.reserve (poses.size ());
    for (const auto& pose : poses)
    {
      SyntheticView v;
      v.view = renderer.render (pose);
      v.resolution = viewResolution (v.view);
      addScannerArtifacts (v.view, params.artifacts, artifact_rng);
      // Noise is scaled by the clean view's own resolution, as in Section 7.5.
      if (params.noise_sigma_resolutions > 0.0)
        addViewingDirectionNoise (*v.view.cloud, v.view.viewpoint, params.noise_sigma_resolutions * v.resolution, rng);
      views.push_back (std::move (v));
    }
    return views;
  }

  std::vector<SyntheticView>
  renderSyntheticViews (const ScanMesh& model, const ViewDirections& directions, const SyntheticViewParams& params)
  {
    const ViewTarget target = boundingTarget (model);
    SyntheticViewParams fitted = params;
    // A pushbroom sweeps the object's width like an orthographic camera and fans over its height.
    if (fitted.camera.orthographic || fitted.camera.pushbroom)
      fitted.camera.ortho_extent = fittingOrthoExtent (target, fitted.camera, params.margin);
    const double distance = fittingDistance (target, fitted.camera, params.margin);
    return renderSyntheticViews (model, lookAtPoses (directions, target, distance, params.up), fitted);
  }
}
