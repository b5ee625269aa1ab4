/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_viewpoint.h>
#include <pcl/io/tensor_view_cache.h>

#include <cstdint>
#include <string>

namespace pcl
{
  namespace io
  {
    /** \brief The key of the sensor a scan file was read with: the file's bytes (its hashFileContents()) and
      * how the sensor was chosen (\a how: e.g. the tool's --viewpoint option, empty for the file's own or
      * fitted sensor). A run that finds the sensor, and the view's meshes under the key it gives, needs not
      * read the scan at all: on 104 cached views, reading and fitting them was half the loading.
      * \ingroup io
      */
    TensorViewCacheKey
    scanSensorKey (std::uint64_t source, const std::string& how);

    /** \brief Store the sensor of view \a id under \a key (written atomically).
      * \throw pcl::IOException when the entry cannot be written
      * \ingroup io
      */
    void
    saveScanSensor (const TensorViewCache& cache, const std::string& id, const TensorViewCacheKey& key,
                    const ScanViewpoint& viewpoint);

    /** \brief The sensor of view \a id when its entry is VALID for \a key and decodes whole (else \a viewpoint
      * is untouched and false is returned).
      * \throw pcl::IOException when the entry exists but cannot be read
      * \ingroup io
      */
    bool
    loadScanSensor (const TensorViewCache& cache, const std::string& id, const TensorViewCacheKey& key,
                    ScanViewpoint& viewpoint);
  }
}
