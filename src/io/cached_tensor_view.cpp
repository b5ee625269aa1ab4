/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/cached_tensor_view.h>
#include <pcl/io/pair_score_cache.h>
#include <pcl/common/tensor_exceptions.h>
#include "../common/parallel_for.h"

#include <mutex>

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

    namespace
    {
      /** The view prepared (prepareTensorView(), centred) and stored in \a cache. */
      pcl::registration::TensorView::Ptr
      prepareAndStore (const TensorViewCache& cache, const std::string& id, const TensorViewCacheKey& key,
                       const pcl::PointCloud<pcl::PointXYZ>& cloud, const ScanViewpoint& viewpoint,
                       const ScanPreparationParams& params, CachedViewReport& report)
      {
        auto view = pcl::registration::prepareTensorView (cloud, viewpoint, params);
        cache.saveView (id, key, *view);
        report.meshes_computed = true;
        return view;
      }
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
      return prepareAndStore (cache, id, key, cloud, viewpoint, params, report);
    }

    pcl::registration::TensorView::Ptr
    cachedExtents (const TensorViewCache& cache, const std::string& id, const TensorViewCacheKey& key,
                   const pcl::PointCloud<pcl::PointXYZ>& cloud, const ScanViewpoint& viewpoint,
                   const ScanPreparationParams& params, Eigen::Vector3d& extents, CachedViewReport& report)
    {
      report.meshes_found = cache.loadExtents (id, key, extents);
      if (report.meshes_found == CacheEntryState::VALID)
        return nullptr;
      auto view = prepareAndStore (cache, id, key, cloud, viewpoint, params, report);
      extents = principalExtents (*view->scan->fine.cloud);  // what saveView stored
      return view;
    }

    pcl::PointCloud<pcl::TensorDescriptor>::Ptr
    cachedTensors (const TensorViewCache& cache, const std::string& id, const TensorViewCacheKey& key,
                   const ObjectDimensions& dims, const pcl::registration::TensorRegistrationParams& params,
                   const pcl::registration::TensorView* view, CachedViewReport& report)
    {
      const std::uint64_t tensor_hash = hashTensorParameters (params);
      pcl::PointCloud<pcl::TensorDescriptor>::Ptr tensors;
      report.tensors_found = cache.loadTensors (id, key, dims, tensor_hash, tensors);
      if (report.tensors_found == CacheEntryState::VALID)
        return tensors;
      pcl::registration::TensorView stored;
      if (!view)
      {
        if (const auto state = cache.loadView (id, key, stored); state != CacheEntryState::VALID)
          PCL_TENSOR_THROW (IOException, "the meshes of view " << id << " turned " << toString (state)
                            << " in the cache during the run (another writer?); run again");
        view = &stored;
      }
      if (!view->scan)
        PCL_TENSOR_THROW (BadArgumentException, "the tensors of view " << id << " need its meshes");
      tensors = pcl::registration::computeViewTensors (*view->scan, dims, params);
      cache.saveTensors (id, key, dims, tensor_hash, *tensors);
      report.tensors_computed = true;
      return tensors;
    }

    void
    addCachedTensors (const TensorViewCache& cache, const std::string& id, const TensorViewCacheKey& key,
                      const ObjectDimensions& dims, const pcl::registration::TensorRegistrationParams& params,
                      pcl::registration::TensorView& view, CachedViewReport& report)
    {
      if (!view.scan)
        PCL_TENSOR_THROW (BadArgumentException, "the tensors of view " << id << " need its meshes");
      view.tensors = cachedTensors (cache, id, key, dims, params, &view, report);
      view.dimensions = dims;
    }

    namespace
    {
      /** D as multiview registration takes it: the given dimensions, sorted, or Eq. 1 over the views. */
      ObjectDimensions
      dimensionsOf (const std::vector<pcl::registration::TensorView::Ptr>& views,
                    const pcl::registration::MultiviewRegistrationParams& params)
      {
        const ObjectDimensions given = givenObjectDimensions (params.object_dimensions);
        if (given.isSet ())
          return given;
        std::vector<const pcl::PointCloud<pcl::PointNormal>*> fine;
        for (const auto& v : views)
          if (v)
            fine.push_back (v->scan->fine.cloud.get ());
        // The function registration itself uses, so that the tensors' D is its D bit for bit.
        return fine.empty () ? ObjectDimensions () : computeObjectDimensions<pcl::PointNormal> (fine);
      }
    }

    namespace
    {
      /** View \a i from the cache alone: its sensor known to \a lookup and its meshes VALID under the key it
        * gives. False (and \a report to be made again) otherwise. */
      bool
      cachedWithoutScan (const TensorViewCache& cache, const MultiviewInputLookup& lookup, std::size_t i,
                         const ScanPreparationParams& preparation, pcl::registration::MultiviewInput& input,
                         pcl::registration::TensorView::Ptr& view, CachedViewReport& report)
      {
        pcl::registration::MultiviewInput known;
        if (!lookup (i, known))
          return false;
        CachedViewReport found;
        found.id = viewIdOf (known.name);
        found.key = viewCacheKey (known.name, preparation, known.viewpoint);
        auto loaded = std::make_shared<pcl::registration::TensorView> ();
        found.meshes_found = cache.loadView (found.id, found.key, *loaded);
        if (found.meshes_found != CacheEntryState::VALID)
          return false;
        found.scan_not_read = true;
        input = known;
        view = loaded;
        report = found;
        return true;
      }
    }

    std::vector<CachedViewReport>
    prepareMultiviewInputs (std::size_t count, const MultiviewInputLoader& load,
                            const pcl::registration::MultiviewRegistrationParams& params, unsigned threads,
                            const TensorViewCache* cache, std::vector<pcl::registration::MultiviewInput>& inputs,
                            const pcl::registration::MultiviewProgress& progress, const MultiviewInputLookup& lookup)
    {
      using pcl::registration::MultiviewStage;
      std::mutex mutex;
      std::size_t done = 0;
      const auto step = [&] (MultiviewStage stage) {
        if (!progress)
          return;
        const std::lock_guard<std::mutex> lock (mutex);
        progress (stage, ++done, count);
      };
      const auto& preparation = params.pairwise.preparation;
      std::vector<CachedViewReport> reports (count);
      std::vector<pcl::registration::TensorView::Ptr> views (count);
      inputs.assign (count, {});
      pcl::detail::parallelFor (count, threads, [&] (std::size_t i) {
        if (cache && lookup && cachedWithoutScan (*cache, lookup, i, preparation, inputs[i], views[i], reports[i]))
        {
          step (MultiviewStage::PREPARATION);
          return;
        }
        auto& input = inputs[i] = load (i);
        if (!input.cloud)
          return;
        try
        {
          if (cache)
          {
            reports[i].id = viewIdOf (input.name);
            reports[i].key = viewCacheKey (input.name, preparation, input.viewpoint);
            views[i] = cachedView (*cache, reports[i].id, reports[i].key, *input.cloud, input.viewpoint, preparation, reports[i]);
          }
          else
          {
            views[i] = pcl::registration::prepareTensorView (*input.cloud, input.viewpoint, preparation);
            reports[i].meshes_computed = true;
          }
          input.cloud.reset ();
        }
        catch (const InvalidScanException&)
        {
          // Left to registration, which reports the view as unusable and says why.
        }
        step (MultiviewStage::PREPARATION);
      });
      const ObjectDimensions dims = dimensionsOf (views, params);
      done = 0;
      pcl::detail::parallelFor (count, threads, [&] (std::size_t i) {
        if (!views[i])
          return;
        try
        {
          if (cache)
            addCachedTensors (*cache, reports[i].id, reports[i].key, dims, params.pairwise, *views[i], reports[i]);
          else
          {
            views[i] = pcl::registration::withTensors (*views[i], dims, params.pairwise);
            reports[i].tensors_computed = true;
          }
        }
        catch (const InvalidScanException&)
        {
          // Registration computes them again and reports the view.
        }
        inputs[i].view = views[i];
        step (MultiviewStage::TENSORS);
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

    pcl::registration::ViewPairScoreCache
    cachedPairScores (const TensorViewCache& cache, const std::vector<CachedViewReport>& views)
    {
      return [&cache, views] (const ObjectDimensions& dims, const pcl::registration::TensorRegistrationParams& params,
                              const pcl::registration::ViewPairRankingParams& ranking) {
        const auto known = std::make_shared<PairScoreCache> (cache);
        const std::uint64_t settings = hashRankingSettings (dims, params, ranking);
        const auto key = [views, settings] (int a, int b) { return pairScoreKey (views.at (a).key, views.at (b).key, settings); };
        pcl::registration::ViewPairScoreMemo memo;
        memo.find = [known, key] (int a, int b, double& score) { return known->find (key (a, b), score); };
        memo.keep = [known, key] (const std::vector<pcl::registration::ViewPairCandidate>& pairs) {
          if (pairs.empty ())
            return;
          std::vector<std::pair<TensorViewCacheKey, double>> scores;
          scores.reserve (pairs.size ());
          for (const auto& p : pairs)
            scores.emplace_back (key (p.first, p.second), p.score);
          known->keep (scores);
        };
        return memo;
      };
    }
  }
}
