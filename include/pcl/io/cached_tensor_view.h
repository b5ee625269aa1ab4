/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/io/content_hash.h>
#include <pcl/io/tensor_view_cache.h>
#include <pcl/registration/multiview_tensor_registration.h>

#include <functional>
#include <vector>

namespace pcl
{
  namespace io
  {
    /** \brief What the cache held for one view, and what had to be computed. */
    struct CachedViewReport
    {
      std::string id;           ///< the view's entry name (viewIdOf())
      TensorViewCacheKey key;   ///< its file and preparation
      CacheEntryState meshes_found = CacheEntryState::MISSING;
      CacheEntryState tensors_found = CacheEntryState::MISSING;
      bool meshes_computed = false;
      bool tensors_computed = false;
      /** Its sensor came from a lookup (MultiviewInputLookup) and its meshes from the cache: its scan was not read. */
      bool scan_not_read = false;
    };

    /** \brief The key of a view file: its bytes, and the settings and sensor it is prepared with. */
    TensorViewCacheKey
    viewCacheKey (const std::string& file, const ScanPreparationParams& params, const ScanViewpoint& viewpoint);

    /** \brief A view's meshes from \a cache when its entry is VALID for \a key, else prepared
      * (prepareTensorView(), centred) and stored: what pcl_tensor_prepare and pcl_tensor_model share.
      * \throw pcl::InvalidScanException when the view cannot be meshed, pcl::IOException when the entry
      * cannot be written */
    pcl::registration::TensorView::Ptr
    cachedView (const TensorViewCache& cache, const std::string& id, const TensorViewCacheKey& key,
                const pcl::PointCloud<pcl::PointXYZ>& cloud, const ScanViewpoint& viewpoint,
                const ScanPreparationParams& params, CachedViewReport& report);

    /** \brief A view's principalExtents() (Eq. 1 for one view) from its meshes entry in \a cache when VALID
      * for \a key, without decoding the meshes, else the view prepared as cachedView() prepares it, stored,
      * and returned with its extents: what D over many views needs.
      * \return the view when it was prepared here, null when the entry was kept
      * \throw as cachedView() */
    pcl::registration::TensorView::Ptr
    cachedExtents (const TensorViewCache& cache, const std::string& id, const TensorViewCacheKey& key,
                   const pcl::PointCloud<pcl::PointXYZ>& cloud, const ScanViewpoint& viewpoint,
                   const ScanPreparationParams& params, Eigen::Vector3d& extents, CachedViewReport& report);

    /** \brief A view's tensors for D = \a dims from \a cache when VALID, else computed (computeViewTensors())
      * from \a view's meshes, or when \a view is null from the meshes entry in \a cache, and stored.
      * \throw pcl::IOException when the meshes are needed and their entry is not VALID (another writer
      * changed it during the run) or the tensors cannot be written */
    pcl::PointCloud<pcl::TensorDescriptor>::Ptr
    cachedTensors (const TensorViewCache& cache, const std::string& id, const TensorViewCacheKey& key,
                   const ObjectDimensions& dims, const pcl::registration::TensorRegistrationParams& params,
                   const pcl::registration::TensorView* view, CachedViewReport& report);

    /** \brief \a view's tensors for D = \a dims (cachedTensors()) set in it. \a view must hold its meshes. */
    void
    addCachedTensors (const TensorViewCache& cache, const std::string& id, const TensorViewCacheKey& key,
                      const ObjectDimensions& dims, const pcl::registration::TensorRegistrationParams& params,
                      pcl::registration::TensorView& view, CachedViewReport& report);

    /** \brief Loads view \a i of a set: its name (its file), cloud and viewpoint. Called from several threads. */
    using MultiviewInputLoader = std::function<pcl::registration::MultiviewInput (std::size_t i)>;

    /** \brief View \a i's name (its file) and sensor without reading its scan, when they are known (e.g.
      * kept in the cache by an earlier read, loadScanSensor()): true and \a input filled, its cloud null;
      * false otherwise. Called from several threads. */
    using MultiviewInputLookup = std::function<bool (std::size_t i, pcl::registration::MultiviewInput& input)>;

    /** \brief The \a count views of a set ready to register, on \a threads threads (0: every core): each
      * loaded, its meshes (prepareTensorView()) taken from \a cache when VALID or computed (and stored
      * when \a cache is given), then D (params.object_dimensions when given, else Eq. 1 over all the
      * views, as MultiviewTensorRegistration takes it), then its tensors likewise. A view's cloud is
      * released once it is meshed, so the set's raw scans are never all in memory at once; a view that
      * cannot be meshed keeps its cloud, and registration reports why.
      * \param[out] inputs the views, each with its prepared view (MultiviewInput::view)
      * \param[in] progress called as views are meshed (PREPARATION) and their tensors computed (TENSORS),
      *            one call at a time
      * \param[in] lookup with \a cache: a view whose sensor it knows and whose meshes are VALID under the key
      *            that sensor gives is not loaded at all (its scan is neither read nor kept)
      * \return what the cache held for each view (all MISSING without a cache) */
    std::vector<CachedViewReport>
    prepareMultiviewInputs (std::size_t count, const MultiviewInputLoader& load,
                            const pcl::registration::MultiviewRegistrationParams& params, unsigned threads,
                            const TensorViewCache* cache, std::vector<pcl::registration::MultiviewInput>& inputs,
                            const pcl::registration::MultiviewProgress& progress = {}, const MultiviewInputLookup& lookup = {});

    /** \brief Pair registrations answered from \a cache when a VALID entry exists for both views' keys,
      * D and the settings (pairCacheKey()), else registered (registerTensorViews()) and stored, for
      * MultiviewTensorRegistration::setPairRegistration(). \a views: prepareMultiviewInputs()' reports, in
      * the order of the views; \a cache must outlive the returned function. */
    pcl::registration::ViewPairRegistration
    cachedPairRegistration (const TensorViewCache& cache, const std::vector<CachedViewReport>& views);

    /** \brief Ranking scores answered from \a cache's PairScoreCache when it holds one for both views' keys
      * and the settings (pairScoreKey()), the others computed and kept there, for
      * MultiviewTensorRegistration::setPairScoreCache(): a run with one view added scores only that view's
      * pairs. \a views: prepareMultiviewInputs()' reports, in the order of the views; \a cache must
      * outlive the returned function. */
    pcl::registration::ViewPairScoreCache
    cachedPairScores (const TensorViewCache& cache, const std::vector<CachedViewReport>& views);
  }
}
