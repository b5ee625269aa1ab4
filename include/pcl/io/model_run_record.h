/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/io/tensor_view_cache.h>
#include <pcl/registration/multiview_tensor_registration.h>
#include <pcl/surface/scan_volumetric_integration.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace pcl
{
  namespace io
  {
    /** \brief What one whole run of pcl_tensor_model gave: its report, its exit code and the files it
      * wrote, each with the hash of its bytes. A run with the same inputs and settings whose outputs
      * are still those bytes has nothing new to compute (the cache's make-like last step). */
    struct ModelRunRecord
    {
      std::string report;     ///< the JSON summary
      std::string messages;   ///< what it said on stderr (views left out)
      int exit_code = 0;
      std::vector<std::pair<std::string, std::uint64_t>> outputs;
    };

    /** \brief The key of a run: every view file (its path and the hash of its bytes, in order) and
      * every setting that changes the outputs, as the caller lists them. */
    TensorViewCacheKey
    modelRunKey (const std::vector<std::string>& view_files, const std::vector<std::string>& settings);

    /** \brief A hash of every setting a model run's outputs depend on besides its views, defaults
      * included: \a registration (the pair settings as pairCacheKey() takes them, the ranking, global
      * verification, the search and the global step) and \a integration. Given to modelRunKey() among the
      * settings, it makes a run recorded before a library's defaults changed be made again, never
      * replayed with the old answers. */
    std::uint64_t
    hashModelRunSettings (const pcl::registration::MultiviewRegistrationParams& registration,
                          const pcl::VolumetricIntegrationParams& integration);

    /** \brief Store \a record under \a key. \throw pcl::IOException when the entry cannot be written */
    void
    saveModelRun (const TensorViewCache& cache, const TensorViewCacheKey& key, const ModelRunRecord& record);

    /** \brief The record of a run with \a key, when its entry is VALID and every output it names still
      * holds the bytes it wrote; false otherwise (the run must be made). */
    bool
    loadModelRun (const TensorViewCache& cache, const TensorViewCacheKey& key, ModelRunRecord& record);
  }
}
