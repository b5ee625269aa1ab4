/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/surface/scan_preparation.h>
#include <pcl/surface/quadric_mesh_reduction.h>
#include <pcl/surface/range_scan_triangulation.h>

namespace pcl
{
  PreparedScan
  prepareScan (const pcl::PointCloud<pcl::PointXYZ>& cloud, const ScanViewpoint& viewpoint,
               const ScanPreparationParams& params)
  {
    RangeScanTriangulation triangulation;
    triangulation.setViewpoint (viewpoint);
    triangulation.setEdgeStdDevs (params.edge_std_devs);
    QuadricMeshReduction reduction;
    reduction.setTargetFaces (params.target_faces);
    ScanMeshNormalEstimation normals;
    normals.setMethod (params.normal_method);
    normals.setRadiusResolutions (params.normal_radius_resolutions);

    PreparedScan scan;
    triangulation.triangulate (cloud, scan.fine);
    scan.resolution = meshResolution (scan.fine);
    reduction.reduce (scan.fine, scan.reduced);
    normals.compute (scan.reduced, scan.fine);
    return scan;
  }
}
