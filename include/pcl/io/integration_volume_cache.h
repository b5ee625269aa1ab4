/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/io/tensor_view_cache.h>
#include <pcl/registration/multiview_point_to_plane_icp.h>
#include <pcl/surface/integration_volume.h>
#include <pcl/surface/scan_volumetric_integration.h>

#include <string>
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

    /** \brief The name of the one voxel entry a model keeps in a cache: from the absolute path of the .conf
      * that holds its poses, which is what a run that extends the model is given (pcl_tensor_model
      * --keep-poses), and so that each run of a model replaces its voxels rather than adding to them
      * (a 104-view model's are 6.5 MB).
      * \ingroup io
      */
    std::string
    integrationVolumeId (const std::string& poses_file);

    /** \brief Store \a volume in \a cache as entry \a id, under \a key (written atomically, replacing the
      * entry's former voxels).
      * \throw pcl::IOException when the entry cannot be written; pcl::BadArgumentException when the
      * volume's sizes do not agree
      * \ingroup io
      */
    void
    saveIntegrationVolume (const TensorViewCache& cache, const std::string& id, const TensorViewCacheKey& key,
                           const IntegrationVolume& volume);

    /** \brief The voxels of entry \a id when it is VALID for \a key and decodes whole; null otherwise (the
      * views must be integrated again).
      * \throw pcl::IOException when the entry exists but cannot be read
      * \ingroup io
      */
    IntegrationVolume::Ptr
    loadIntegrationVolume (const TensorViewCache& cache, const std::string& id, const TensorViewCacheKey& key);
  }
}
