/*
 * pcl_tensor evaluation: FPFH + SampleConsensusPrerejective baseline, then ICP.
 */
#include "fpfh_baseline.h"

#include <pcl/common/io.h>
#include <pcl/common/time.h>
#include <pcl/features/fpfh.h>
#include <pcl/features/normal_3d.h>
#include <pcl/filters/filter.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/registration/point_to_plane_icp.h>
#include <pcl/registration/sample_consensus_prerejective.h>

#include <cstdlib>

namespace pcl_tensor_eval
{
  namespace
  {
    using CloudN = pcl::PointCloud<pcl::PointNormal>;

    /** The tutorial's normals point toward an origin viewpoint; ours must point toward the sensor,
      * which for the Stanford scans is orthographic (+z) and has no position to hand to PCL. */
    void
    orientTowardSensor (CloudN& cloud, const pcl::ScanViewpoint& viewpoint)
    {
      for (auto& p : cloud)
        if (p.getNormalVector3fMap ().cast<double> ().dot (viewpoint.towardSensor (p.getVector3fMap ().cast<double> ())) < 0.0)
          p.getNormalVector3fMap () *= -1.0f;
    }
  }

  FpfhView
  computeFpfhView (const pcl::PointCloud<pcl::PointXYZ>& cloud, const pcl::ScanViewpoint& viewpoint, double resolution,
                   const FpfhBaselineParams& params)
  {
    pcl::StopWatch watch;
    const float leaf = static_cast<float> (params.leaf_resolutions * resolution);
    // Single-threaded estimators (not the tutorial's OMP ones): the tensor pipeline runs on one core too.
    pcl::PointCloud<pcl::PointXYZ>::Ptr input (new pcl::PointCloud<pcl::PointXYZ> (cloud));
    input->is_dense = false;  // let VoxelGrid skip the NaN holes of organized scans
    pcl::PointCloud<pcl::PointXYZ>::Ptr down (new pcl::PointCloud<pcl::PointXYZ>);
    pcl::VoxelGrid<pcl::PointXYZ> grid;
    grid.setLeafSize (leaf, leaf, leaf);
    grid.setInputCloud (input);
    grid.filter (*down);

    FpfhView view;
    pcl::copyPointCloud (*down, *view.points);
    pcl::NormalEstimation<pcl::PointXYZ, pcl::PointNormal> normals;
    normals.setRadiusSearch (params.normal_radius_leaves * leaf);
    normals.setInputCloud (down);
    normals.compute (*view.points);
    orientTowardSensor (*view.points, viewpoint);
    // Points with too few neighbours get NaN normals; FPFH and the kd-trees must not see them.
    pcl::Indices finite;
    pcl::removeNaNNormalsFromPointCloud (*view.points, *view.points, finite);

    pcl::FPFHEstimation<pcl::PointNormal, pcl::PointNormal, pcl::FPFHSignature33> fpfh;
    fpfh.setRadiusSearch (params.feature_radius_leaves * leaf);
    fpfh.setInputCloud (view.points);
    fpfh.setInputNormals (view.points);
    fpfh.compute (*view.features);
    view.time_ms = watch.getTime ();
    return view;
  }

  FpfhResult
  registerFpfh (const FpfhView& model, const FpfhView& scene, double resolution, const FpfhBaselineParams& params,
                const pcl::registration::TensorVerificationParams& icp_params)
  {
    FpfhResult result;
    pcl::StopWatch watch;
    const float leaf = static_cast<float> (params.leaf_resolutions * resolution);
    pcl::SampleConsensusPrerejective<pcl::PointNormal, pcl::PointNormal, pcl::FPFHSignature33> align;
    align.setInputSource (scene.points);
    align.setSourceFeatures (scene.features);
    align.setInputTarget (model.points);
    align.setTargetFeatures (model.features);
    align.setMaximumIterations (params.max_iterations);
    align.setNumberOfSamples (params.samples);
    align.setCorrespondenceRandomness (params.correspondence_randomness);
    align.setSimilarityThreshold (params.similarity_threshold);
    align.setMaxCorrespondenceDistance (params.inlier_distance_leaves * leaf);
    align.setInlierFraction (params.inlier_fraction);
    std::srand (params.seed);  // PCL samples with std::rand(); this makes every pair reproducible
    CloudN aligned;
    align.align (aligned);
    result.sac_ms = watch.getTime ();
    result.registered = align.hasConverged ();
    result.inliers = align.getInliers ().size ();
    if (!result.registered)
      return result;

    watch.reset ();
    // The tensor verification's own point-to-plane ICP, with its iterations and distances.
    pcl::registration::PointToPlaneIcpParams icp;
    icp.max_iterations = icp_params.icp_iterations;
    icp.max_distance = icp_params.icp_max_distance * resolution;
    icp.final_distance = icp_params.icp_final_distance * resolution;
    icp.coarse_stage_step = icp_params.icp_coarse_stage_step;
    pcl::BoundedNearestSearch search (static_cast<float> (icp.max_distance));
    search.setInputCloud (*model.points);
    result.transform = pcl::registration::pointToPlaneIcp (*scene.points, *model.points, search,
                                                           align.getFinalTransformation (), icp).transform;
    result.icp_ms = watch.getTime ();
    return result;
  }
}
