/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/surface/scan_preparation.h>
#include <pcl/common/scan_noise.h>
#include <pcl/surface/quadric_mesh_reduction.h>
#include <pcl/surface/range_scan_triangulation.h>
#include <pcl/surface/speck_removal.h>
#include <pcl/surface/stray_fragment_removal.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/common/point_tests.h>

#include <algorithm>
#include <cmath>

namespace pcl
{
  namespace
  {
    /** The three stages of Section 2, configured from \a params (their setters check the values). */
    struct PreparationStages
    {
      PreparationStages (const ScanViewpoint& viewpoint, const ScanPreparationParams& params)
      {
        triangulation.setViewpoint (viewpoint);
        triangulation.setEdgeStdDevs (params.edge_std_devs);
        reduction.setTargetFaces (params.target_faces);
        normals.setMethod (params.normal_method);
        normals.setRadiusResolutions (params.normal_radius_resolutions);
        if (params.reduction_grid_step < 1)
          PCL_TENSOR_THROW (BadArgumentException, "the reduction's grid step must be at least 1, got " << params.reduction_grid_step);
        if (!(params.stray_fragment_gap > 0.0) || !std::isfinite (params.stray_fragment_gap)
            || !(params.stray_fragment_fraction >= 0.0 && params.stray_fragment_fraction < 1.0))
          PCL_TENSOR_THROW (BadArgumentException, "stray fragments: the gap must be positive and finite and the fraction in [0, 1), got "
                            << params.stray_fragment_gap << " and " << params.stray_fragment_fraction);
        checkSpeckParameters (params.speck_max_pixels, params.speck_jump);
      }
      RangeScanTriangulation triangulation;
      QuadricMeshReduction reduction;
      ScanMeshNormalEstimation normals;
    };
  }

  namespace
  {
    /** The mesh of every params.reduction_grid_step-th row and column of an organized \a cloud, or
      * an empty mesh when M_i itself is to be reduced. */
    ScanMesh
    reductionInput (const pcl::PointCloud<pcl::PointXYZ>& cloud, const PreparationStages& stages,
                    const ScanPreparationParams& params, double resolution)
    {
      ScanMesh coarse;
      const auto step = static_cast<std::uint32_t> (params.reduction_grid_step);
      if (step <= 1 || !cloud.isOrganized ())
        return coarse;
      pcl::PointCloud<pcl::PointXYZ> grid;
      grid.reserve (static_cast<std::size_t> ((cloud.width + step - 1) / step) * ((cloud.height + step - 1) / step));
      std::size_t finite = 0;
      for (std::uint32_t r = 0; r < cloud.height; r += step)
        for (std::uint32_t c = 0; c < cloud.width; c += step)
        {
          grid.push_back (cloud.at (c, r));
          finite += pcl::isXYZFinite (grid.back ()) ? 1 : 0;
        }
      // Too few points left for the target: reduce M_i itself.
      if (finite < 4 * static_cast<std::size_t> (params.target_faces))
        return coarse;
      grid.width = (cloud.width + step - 1) / step;
      grid.height = (cloud.height + step - 1) / step;
      grid.is_dense = finite == grid.size ();
      stages.triangulation.triangulate (grid, coarse);
      if (!coarse.polygons.empty ())
        removeStrayFragments (coarse, params.stray_fragment_gap * resolution, params.stray_fragment_fraction);
      return coarse;
    }
  }

  namespace
  {
    /** \a cloud, or its copy in \a storage without its specks when it has any: most scans have none,
      * and are not copied. */
    const pcl::PointCloud<pcl::PointXYZ>&
    withoutSpecks (const pcl::PointCloud<pcl::PointXYZ>& cloud, const ScanViewpoint& viewpoint,
                   const ScanPreparationParams& params, pcl::PointCloud<pcl::PointXYZ>& storage)
    {
      const std::vector<bool> speck = speckPixels (cloud, viewpoint, params.speck_max_pixels, params.speck_jump);
      if (std::find (speck.begin (), speck.end (), true) == speck.end ())
        return cloud;
      storage = cloud;
      removeSpecks (storage, speck);
      return storage;
    }
  }

  PreparedScan
  prepareScan (const pcl::PointCloud<pcl::PointXYZ>& input, const ScanViewpoint& viewpoint,
               const ScanPreparationParams& params)
  {
    const PreparationStages stages (viewpoint, params);
    pcl::PointCloud<pcl::PointXYZ> storage;
    const pcl::PointCloud<pcl::PointXYZ>& cloud = withoutSpecks (input, viewpoint, params, storage);
    PreparedScan scan;
    stages.triangulation.triangulate (cloud, scan.fine);
    // d_res of the whole mesh sets the gap; the fragments hold too few points to change it.
    scan.resolution = meshResolution (scan.fine);
    removeStrayFragments (scan.fine, params.stray_fragment_gap * scan.resolution, params.stray_fragment_fraction);
    const ScanMesh coarse = reductionInput (cloud, stages, params, scan.resolution);
    stages.reduction.reduce (coarse.polygons.empty () ? scan.fine : coarse, scan.reduced);
    stages.normals.compute (scan.reduced, scan.fine, scan.resolution);
    scan.noise = estimateScanNoise (*scan.fine.cloud, 3.0 * scan.resolution);
    // M_i is kept for the whole run: give back what was reserved for every pixel of the image.
    scan.fine.cloud->points.shrink_to_fit ();
    scan.fine.polygons.shrink_to_fit ();
    return scan;
  }

  void
  checkScanPreparationParams (const ScanPreparationParams& params)
  {
    const PreparationStages stages (ScanViewpoint::fromPositiveZ (), params);
    (void) stages;
  }
}
