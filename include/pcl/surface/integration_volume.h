/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/memory.h>

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace pcl
{
  /** \brief The voxels that volumetric integration made of some views (ScanVolumetricIntegration::getVolume()),
    * kept so that more views of the same model can be added to them later without integrating the
    * first ones again (ScanVolumetricIntegration::setInitialVolume()), e.g. from a cache.
    *
    * Voxel (i, j, k) sits at (i, j, k) * voxel_size in the world frame, in the 8^3 block
    * floor((i, j, k) / 8); each block holds 512 voxels, x fastest, each a weighted mean signed
    * distance and its weight (Curless & Levoy, 1996).
    * \ingroup surface
    */
  struct IntegrationVolume
  {
    using Ptr = shared_ptr<IntegrationVolume>;
    using ConstPtr = shared_ptr<const IntegrationVolume>;

    /** Voxels per block. */
    static constexpr std::size_t kBlockVoxels = 512;

    /** The voxel edge, in the units of the views. */
    double voxel_size = 0.0;
    /** The views integrated into it, and the sum of their d_res (their mean sets the z-buffers' density). */
    std::size_t views = 0;
    double resolution_sum = 0.0;
    /** The blocks' integer coordinates, in the order they were allocated. */
    std::vector<Eigen::Vector3i> blocks;
    /** kBlockVoxels per block, in the order of \a blocks. */
    std::vector<float> distance, weight;

    /** True when the sizes agree: one distance and one weight per voxel of every block, and a positive voxel. */
    bool
    isConsistent () const
    {
      return voxel_size > 0.0 && distance.size () == blocks.size () * kBlockVoxels && weight.size () == distance.size ();
    }
  };
}
