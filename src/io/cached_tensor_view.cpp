/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/cached_tensor_view.h>
#include <pcl/common/tensor_exceptions.h>
#include "../common/parallel_for.h"

#include <algorithm>
#include <functional>

namespace pcl
{
  namespace io
  {
    TensorViewCacheKey
    viewCacheKey (const std::string& file, const ScanPreparationParams& params, const ScanViewpoint& viewpoint)
    {
      TensorViewCacheKey key;
      key.source = hashFileContents (file);
      key.preparation = hashPreparation (params, viewpoint);
      return key;
    }

    pcl::registration::TensorView::Ptr
    cachedView (const TensorViewCache& cache, const std::string& id, const TensorViewCacheKey& key,
                const pcl::PointCloud<pcl::PointXYZ>& cloud, const ScanViewpoint& viewpoint,
                const ScanPreparationParams& params, CachedViewReport& report)
    {
      auto view = std::make_shared<pcl::registration::TensorView> ();
      report.meshes_found = cache.loadView (id, key, *view);
      if (report.meshes_found == CacheEntryState::VALID)
        return view;
      view = pcl::registration::prepareTensorView (cloud, viewpoint, params);
      cache.saveView (id, key, *view);
      report.meshes_computed = true;
      return view;
    }

    void
    addCachedTensors (const TensorViewCache& cache, const std::string& id, const TensorViewCacheKey& key,
                      const ObjectDimensions& dims, const pcl::registration::TensorRegistrationParams& params,
                      pcl::registration::TensorView& view, CachedViewReport& report)
    {
      if (!view.scan)
        PCL_TENSOR_THROW (BadArgumentException, "the tensors of view " << id << " need its meshes");
      const std::uint64_t tensor_hash = hashTensorParameters (params);
      pcl::PointCloud<pcl::TensorDescriptor>::Ptr tensors;
      report.tensors_found = cache.loadTensors (id, key, dims, tensor_hash, tensors);
      if (report.tensors_found != CacheEntryState::VALID)
      {
        tensors = pcl::registration::computeViewTensors (*view.scan, dims, params);
        cache.saveTensors (id, key, dims, tensor_hash, *tensors);
        report.tensors_computed = true;
      }
      view.tensors = tensors;
      view.dimensions = dims;
    }

    std::vector<CachedViewReport>
    prepareCachedViews (const TensorViewCache& cache, std::vector<pcl::registration::MultiviewInput>& inputs,
                        const pcl::registration::MultiviewRegistrationParams& params, unsigned threads)
    {
      const auto& preparation = params.pairwise.preparation;
      std::vector<CachedViewReport> reports (inputs.size ());
      std::vector<TensorViewCacheKey> keys (inputs.size ());
      std::vector<std::string> ids (inputs.size ());
      std::vector<pcl::registration::TensorView::Ptr> views (inputs.size ());
      pcl::detail::parallelFor (inputs.size (), threads, [&] (std::size_t i) {
        auto& input = inputs[i];
        ids[i] = reports[i].id = viewIdOf (input.name);
        keys[i] = reports[i].key = viewCacheKey (input.name, preparation, input.viewpoint);
        try
        {
          if (input.cloud)
            views[i] = cachedView (cache, ids[i], keys[i], *input.cloud, input.viewpoint, preparation, reports[i]);
        }
        catch (const InvalidScanException&)
        {
          // Left to registration, which reports the view as unusable and says why.
        }
      });
      ObjectDimensions dims;
      dims.D = params.object_dimensions;
      std::sort (dims.D.data (), dims.D.data () + 3, std::greater<> ());
      if (!(dims.D.array () > 0.0).all ())
      {
        dims.D.setZero ();
        for (const auto& v : views)
          if (v)
            dims.D = dims.D.cwiseMax (pcl::principalExtents (*v->scan->fine.cloud));  // Eq. 1, as registration takes it
      }
      pcl::detail::parallelFor (inputs.size (), threads, [&] (std::size_t i) {
        if (!views[i])
          return;
        try
        {
          addCachedTensors (cache, ids[i], keys[i], dims, params.pairwise, *views[i], reports[i]);
        }
        catch (const InvalidScanException&)
        {
          // Registration computes them again and reports the view.
        }
        inputs[i].view = views[i];
        inputs[i].cloud.reset ();
      });
      return reports;
    }

    pcl::registration::ViewPairRegistration
    cachedPairRegistration (const TensorViewCache& cache, const std::vector<CachedViewReport>& views)
    {
      return [&cache, views] (int model, int scene, const pcl::registration::TensorView::ConstPtr& model_view,
                              const pcl::registration::TensorView::ConstPtr& scene_view, const ObjectDimensions& dims,
                              const pcl::registration::TensorRegistrationParams& params) {
        const TensorViewCacheKey key = pairCacheKey (views.at (model).key, views.at (scene).key, dims, params);
        pcl::registration::TensorRegistrationReport report;
        if (cache.loadPair (views[model].id, views[scene].id, key, report) == CacheEntryState::VALID)
          return report;
        report = pcl::registration::registerTensorViews (model_view, scene_view, dims, params);
        cache.savePair (views[model].id, views[scene].id, key, report);
        return report;
      };
    }
  }
}
