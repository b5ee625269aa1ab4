/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/surface/scan_preparation.h>
#include <pcl/common/scan_noise.h>
#include <pcl/surface/quadric_mesh_reduction.h>
#include <pcl/surface/range_scan_triangulation.h>
#include <pcl/surface/stray_fragment_removal.h>
#include <pcl/common/tensor_exceptions.h>

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
        if (!(params.stray_fragment_gap > 0.0) || !std::isfinite (params.stray_fragment_gap)
            || !(params.stray_fragment_fraction >= 0.0 && params.stray_fragment_fraction < 1.0))
          PCL_TENSOR_THROW (BadArgumentException, "stray fragments: the gap must be positive and finite and the fraction in [0, 1), got "
                            << params.stray_fragment_gap << " and " << params.stray_fragment_fraction);
      }
      RangeScanTriangulation triangulation;
      QuadricMeshReduction reduction;
      ScanMeshNormalEstimation normals;
    };
  }

  PreparedScan
  prepareScan (const pcl::PointCloud<pcl::PointXYZ>& cloud, const ScanViewpoint& viewpoint,
               const ScanPreparationParams& params)
  {
    const PreparationStages stages (viewpoint, params);
    PreparedScan scan;
    stages.triangulation.triangulate (cloud, scan.fine);
    // d_res of the whole mesh sets the gap; the fragments hold too few points to change it.
    scan.resolution = meshResolution (scan.fine);
    removeStrayFragments (scan.fine, params.stray_fragment_gap * scan.resolution, params.stray_fragment_fraction);
    stages.reduction.reduce (scan.fine, scan.reduced);
    stages.normals.compute (scan.reduced, scan.fine, scan.resolution);
    scan.noise = estimateScanNoise (*scan.fine.cloud, 3.0 * scan.resolution);
    return scan;
  }

  void
  checkScanPreparationParams (const ScanPreparationParams& params)
  {
    const PreparationStages stages (ScanViewpoint::fromPositiveZ (), params);
    (void) stages;
  }
}
