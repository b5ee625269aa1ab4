/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/surface/scan_preparation.h>
#include <pcl/common/scan_noise.h>
#include <pcl/surface/quadric_mesh_reduction.h>
#include <pcl/surface/range_scan_triangulation.h>

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
    scan.resolution = meshResolution (scan.fine);
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
