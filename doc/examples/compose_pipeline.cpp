/*
 * pcl_tensor example: pairwise registration composed by hand from the PCL-style pieces, as a user
 * of PCL would wire a feature, a correspondence estimator and a rejector together. It follows the
 * order TensorRegistration uses, and so gets pcl_tensor_register's transform bit for bit on a pair
 * whose first verified hypothesis is also the only one (bun000 <- bun045); TensorRegistration adds
 * the skipping of refuted repeats and the ambiguity check (doc/design.md#ambiguity-check).
 *
 *   compose_pipeline MODEL.ply SCENE.ply     prints {"status": ..., "transform": [...], "icp_transform": [...]}
 */
#include <pcl/common/object_dimensions.h>
#include <pcl/features/tensor.h>
#include <pcl/io/range_scan_io.h>
#include <pcl/io/registration_report_json.h>
#include <pcl/registration/correspondence_estimation_tensor.h>
#include <pcl/registration/correspondence_rejection_tensor_verification.h>
#include <pcl/registration/icp.h>
#include <pcl/registration/tensor_registration_params.h>
#include <pcl/registration/tensor_view.h>

#include <iostream>

using namespace pcl::registration;
using Tensors = pcl::PointCloud<pcl::TensorDescriptor>;

namespace
{
  /** A pcl::Feature: the tensors of one view's reduced mesh (Section 2), with the pipeline's settings. */
  pcl::TensorEstimation<pcl::PointNormal, pcl::PointNormal, pcl::TensorDescriptor>
  tensorEstimation (const TensorView& view, const pcl::ObjectDimensions& dims, const TensorRegistrationParams& params)
  {
    pcl::TensorEstimation<pcl::PointNormal, pcl::PointNormal, pcl::TensorDescriptor> estimation;
    estimation.setInputCloud (view.scan->reduced.cloud);
    estimation.setInputNormals (view.scan->reduced.cloud);
    estimation.setPolygons (view.scan->reduced.polygons);
    estimation.setObjectDimensions (dims);
    estimation.setGridSize (params.grid_size);
    estimation.setPartnersPerVertex (params.partners_per_vertex);
    estimation.setMinNormalAngle (params.min_normal_angle);
    estimation.setRegionGrowing (params.region_growing);
    return estimation;
  }

  /** The correspondence estimator: scene tensor -> model tensor above t_r and t_c (Eq. 5-6). */
  CorrespondenceEstimationTensor
  tensorMatcher (const Tensors::ConstPtr& model_tensors, const TensorRegistrationParams& params)
  {
    CorrespondenceEstimationTensor matcher;
    matcher.setOverlapThreshold (params.overlap_threshold);
    matcher.setCorrelationThreshold (params.correlation_threshold);
    matcher.setThetaBinWidth (params.theta_bin_width);
    matcher.setOrder (params.order);
    matcher.setInputTarget (model_tensors);
    return matcher;
  }

  /** Fig. 7: the scene's tensors batch by batch, each matched and its best matches verified through the
    * rejector's PCL interface (Section 4.1, ICP included) until one passes. \return passed */
  bool
  searchBatches (pcl::TensorEstimation<pcl::PointNormal, pcl::PointNormal, pcl::TensorDescriptor>& scene_estimation,
                 CorrespondenceEstimationTensor& matcher, CorrespondenceRejectorTensorVerification& rejector,
                 const TensorRegistrationParams& params, Eigen::Matrix4f& transform)
  {
    for (int batch = 0; batch < params.scene_tensor_batches; ++batch)
    {
      scene_estimation.setPairBatch (params.scene_tensor_batches, batch);
      Tensors::Ptr scene_tensors (new Tensors);
      scene_estimation.computeOrThrow (*scene_tensors);
      if (scene_tensors->empty ())
        continue;
      matcher.setInputSource (scene_tensors);
      pcl::Correspondences matches, verified;
      matcher.determineCorrespondences (matches);  // best C_c first
      std::vector<TensorMatch> details = matcher.getMatches ();
      const std::size_t budget = std::min<std::size_t> (matches.size (), static_cast<std::size_t> (params.batch_hypotheses));
      matches.resize (budget);
      details.resize (budget);
      rejector.setSceneTensors (scene_tensors);
      rejector.setInputMatches (details);
      rejector.getRemainingCorrespondences (matches, verified);
      if (!verified.empty ())
      {
        transform = rejector.getAcceptedTransforms ().front ();
        return true;
      }
    }
    return false;
  }
}

int
main (int argc, char** argv)
{
  if (argc != 3)
  {
    std::cerr << "usage: " << argv[0] << " MODEL SCENE" << std::endl;
    return 2;
  }
  // 1. The range images and their sensors.
  const pcl::io::RangeScan model_scan = pcl::io::loadRangeScan (argv[1]);
  const pcl::io::RangeScan scene_scan = pcl::io::loadRangeScan (argv[2]);
  const TensorRegistrationParams params;  // pcl_tensor_register's defaults

  // 2. M_i and M'_i with normals, each view centred on its points; D from the two views (Eq. 1).
  const TensorView::Ptr model = prepareTensorView (*model_scan.cloud, model_scan.viewpoint, params.preparation);
  const TensorView::Ptr scene = prepareTensorView (*scene_scan.cloud, scene_scan.viewpoint, params.preparation);
  const pcl::ObjectDimensions dims =
      pcl::computeObjectDimensions<pcl::PointNormal> ({model->scan->fine.cloud.get (), scene->scan->fine.cloud.get ()});

  // 3. The model's tensors, a pcl::Feature computed once.
  Tensors::Ptr model_tensors (new Tensors);
  tensorEstimation (*model, dims, params).computeOrThrow (*model_tensors);

  // 4. The estimator and the rejector, set as TensorRegistration sets them.
  CorrespondenceEstimationTensor matcher = tensorMatcher (model_tensors, params);
  CorrespondenceRejectorTensorVerification rejector;
  rejector.setModel (model->scan, model_tensors);
  rejector.setScene (scene->scan, Tensors::ConstPtr (new Tensors));
  rejector.setObjectDimensions (dims);
  rejector.setParams (params.verification);
  rejector.setMaxAccepted (1);

  // 5. The scene's tensors in batches, matched and verified until one hypothesis passes.
  auto scene_estimation = tensorEstimation (*scene, dims, params);
  Eigen::Matrix4f centred = Eigen::Matrix4f::Identity ();
  const bool registered = searchBatches (scene_estimation, matcher, rejector, params, centred);

  // 6. The transform between the scans' own frames, then a standard pcl::IterativeClosestPoint on top.
  pcl::io::JsonReport report;
  report["status"] = registered ? "registered" : "not_registered";
  if (registered)
  {
    const Eigen::Matrix4f transform = betweenViewFrames (centred, *model, *scene);
    report["transform"] = pcl::io::toJson (transform);
    pcl::IterativeClosestPoint<pcl::PointNormal, pcl::PointNormal> icp;
    pcl::PointCloud<pcl::PointNormal>::Ptr scene_points (new pcl::PointCloud<pcl::PointNormal> (*scene->scan->fine.cloud));
    icp.setInputSource (scene_points);
    icp.setInputTarget (model->scan->fine.cloud);
    icp.setMaxCorrespondenceDistance (2.0 * rejector.getResolution ());
    pcl::PointCloud<pcl::PointNormal> aligned;
    icp.align (aligned, centred);
    report["icp_transform"] = pcl::io::toJson (Eigen::Matrix4f (betweenViewFrames (icp.getFinalTransformation (), *model, *scene)));
  }
  std::cout << pcl::io::dumpJson (report) << std::endl;
  return registered ? 0 : 3;
}
