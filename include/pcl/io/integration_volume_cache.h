/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/io/tensor_view_cache.h>
#include <pcl/registration/multiview_point_to_plane_icp.h>
#include <pcl/surface/integration_volume.h>
#include <pcl/surface/scan_volumetric_integration.h>

#include <vector>

namespace pcl
{
  namespace io
  {
    /** \brief The key of a model's voxels: each of its views' cache key (viewCacheKey()) and pose (by
      * its bit patterns), in the order they were integrated, and every integration setting. A model
      * extended with new views finds the voxels of its old views under the key of their keys and poses.
      * \throw pcl::BadArgumentException when \a views and \a poses differ in size
      * \ingroup io
      */
    TensorViewCacheKey
    integrationVolumeKey (const std::vector<TensorViewCacheKey>& views, const pcl::registration::ViewPoses& poses,
                          const VolumetricIntegrationParams& params);

    /** \brief Store \a volume in \a cache under \a key (written atomically).
      * \throw pcl::IOException when the entry cannot be written; pcl::BadArgumentException when the
      * volume's sizes do not agree
      * \ingroup io
      */
    void
    saveIntegrationVolume (const TensorViewCache& cache, const TensorViewCacheKey& key, const IntegrationVolume& volume);

    /** \brief The voxels stored under \a key when their entry is VALID and decodes whole; null otherwise
      * (the views must be integrated again).
      * \throw pcl::IOException when the entry exists but cannot be read
      * \ingroup io
      */
    IntegrationVolume::Ptr
    loadIntegrationVolume (const TensorViewCache& cache, const TensorViewCacheKey& key);
  }
}
