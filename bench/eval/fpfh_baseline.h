/*
 * pcl_tensor evaluation: the comparison method, FPFH features + pcl::SampleConsensusPrerejective,
 * with the parameters of PCL's tutorial "Robust pose estimation of rigid objects", then ICP.
 */
#pragma once

#include <pcl/common/scan_viewpoint.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/registration/tensor_verification.h>

#include <cstdint>

namespace pcl_tensor_eval
{
  /** \brief The tutorial's parameters. Its lengths are for its own data (leaf 0.005 m); here every
    * length is a multiple of the leaf, and the leaf a multiple of d_res, so that they scale with the
    * scanner's resolution. Tutorial: normals radius 0.01 = 2 leaves, FPFH radius 0.025 = 5 leaves,
    * inliers within 2.5 leaves.
    */
  struct FpfhBaselineParams
  {
    double leaf_resolutions = 2.5;       ///< voxel leaf, in d_res
    double normal_radius_leaves = 2.0;   ///< normal estimation radius, in leaves
    double feature_radius_leaves = 5.0;  ///< FPFH radius, in leaves
    int max_iterations = 50000;
    int samples = 3;
    int correspondence_randomness = 5;
    float similarity_threshold = 0.9f;
    float inlier_distance_leaves = 2.5f;  ///< MaxCorrespondenceDistance, in leaves
    float inlier_fraction = 0.25f;
    /** PCL's SampleConsensusPrerejective draws with std::rand(): it is seeded with this before each pair. */
    unsigned seed = 2006;
  };

  /** \brief One view's downsampled points with normals and their FPFH features. */
  struct FpfhView
  {
    pcl::PointCloud<pcl::PointNormal>::Ptr points{new pcl::PointCloud<pcl::PointNormal>};
    pcl::PointCloud<pcl::FPFHSignature33>::Ptr features{new pcl::PointCloud<pcl::FPFHSignature33>};
    double time_ms = 0.0;
  };

  /** \brief Downsample, estimate normals (oriented toward the sensor) and FPFH features of one view.
    * \param[in] resolution d_res of the view, which sets the leaf
    */
  FpfhView
  computeFpfhView (const pcl::PointCloud<pcl::PointXYZ>& cloud, const pcl::ScanViewpoint& viewpoint,
                   double resolution, const FpfhBaselineParams& params);

  /** \brief What the baseline did on one pair. */
  struct FpfhResult
  {
    bool registered = false;  ///< SampleConsensusPrerejective converged (inlier fraction reached)
    Eigen::Matrix4f transform = Eigen::Matrix4f::Identity ();  ///< scene -> model, after ICP
    std::size_t inliers = 0;
    double sac_ms = 0.0, icp_ms = 0.0;
  };

  /** \brief Align the scene view to the model view with SampleConsensusPrerejective, then refine with
    * the tensor verification's point-to-plane ICP (pcl::registration::pointToPlaneIcp, iterations and
    * distance of \a icp), on the downsampled points.
    * \param[in] resolution d_res of the pair (ICP's distance is in d_res)
    */
  FpfhResult
  registerFpfh (const FpfhView& model, const FpfhView& scene, double resolution, const FpfhBaselineParams& params,
                const pcl::registration::TensorVerificationParams& icp);
}
