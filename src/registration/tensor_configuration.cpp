/*
 * pcl_tensor: the pipeline's components set from TensorRegistrationParams (private to the library).
 */
#include "tensor_configuration.h"

#include <pcl/common/tensor_exceptions.h>

#include <cmath>

namespace pcl
{
  namespace registration
  {
    namespace detail
    {
      void
      configureEstimation (ViewTensorEstimation& estimation, const TensorRegistrationParams& params)
      {
        estimation.setGridSize (params.grid_size);
        estimation.setPartnersPerVertex (params.partners_per_vertex);
        estimation.setMinNormalAngle (params.min_normal_angle);
        estimation.setRegionGrowing (params.region_growing);
      }

      void
      configureViewEstimation (ViewTensorEstimation& estimation, const PreparedScan& scan, const ObjectDimensions& dims,
                               const TensorRegistrationParams& params)
      {
        estimation.setInputCloud (scan.reduced.cloud);
        estimation.setInputNormals (scan.reduced.cloud);
        estimation.setPolygons (scan.reduced.polygons);
        estimation.setObjectDimensions (dims);
        configureEstimation (estimation, params);
      }

      void
      configureMatcher (CorrespondenceEstimationTensor& matcher, const TensorRegistrationParams& params)
      {
        matcher.setOverlapThreshold (params.overlap_threshold);
        matcher.setCorrelationThreshold (params.correlation_threshold);
        matcher.setThetaBinWidth (params.theta_bin_width);
        matcher.setOrder (params.order);
      }

      void
      configureVerifier (CorrespondenceRejectorTensorVerification& verifier, const TensorView& model,
                         const pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr& scene_tensors, const TensorView& scene,
                         const ObjectDimensions& dims, const TensorRegistrationParams& params)
      {
        verifier.setModel (model.scan, model.tensors, model.projections);
        verifier.setScene (scene.scan, scene_tensors, scene.projections);
        verifier.setObjectDimensions (dims);
        verifier.setParams (params.verification);
      }
    }

    void
    checkParams (const TensorRegistrationParams& params)
    {
      checkScanPreparationParams (params.preparation);
      detail::ViewTensorEstimation estimation;
      detail::configureEstimation (estimation, params);
      CorrespondenceEstimationTensor matcher;
      detail::configureMatcher (matcher, params);
      CorrespondenceRejectorTensorVerification verifier;
      verifier.setParams (params.verification);
      if (params.scene_tensor_batches < 1 || params.batch_hypotheses < 0)
        PCL_TENSOR_THROW (BadArgumentException, "the scene's tensors need at least one batch and a non-negative number of "
                          "hypotheses per batch, got " << params.scene_tensor_batches << " and " << params.batch_hypotheses);
      if (!(params.fallback_overlap_threshold >= 0.0f && params.fallback_overlap_threshold <= 1.0f) ||
          !(params.fallback_correlation_threshold >= -1.0f && params.fallback_correlation_threshold <= 1.0f))
        PCL_TENSOR_THROW (BadArgumentException, "the second round's thresholds must be in [0, 1] and [-1, 1], got "
                          << params.fallback_overlap_threshold << " and " << params.fallback_correlation_threshold);
      if (params.max_hypotheses < 0)
        PCL_TENSOR_THROW (BadArgumentException, "the hypothesis cap must be 0 (none) or positive, got " << params.max_hypotheses);
      if (!(params.repeat_rotation >= 0.0 && params.repeat_translation >= 0.0) ||
          !std::isfinite (params.repeat_rotation) || !std::isfinite (params.repeat_translation))
        PCL_TENSOR_THROW (BadArgumentException, "repeat tolerances must be finite and non-negative");
      if (params.ambiguity_checks < 0 || !(params.ambiguity_rotation >= 0.0 && params.ambiguity_rotation <= 180.0))
        PCL_TENSOR_THROW (BadArgumentException, "ambiguity checks must be non-negative and their rotation in [0, 180] degrees, got "
                          << params.ambiguity_checks << " and " << params.ambiguity_rotation);
      if (!(params.rival_margin >= 0.0 && params.rival_margin <= 1.0))
        PCL_TENSOR_THROW (BadArgumentException, "the rival margin must be in [0, 1], got " << params.rival_margin);
      if (!(params.rival_empty_space_margin >= 0.0) || !std::isfinite (params.rival_empty_space_margin) ||
          !(params.rival_empty_space_fraction > 0.0 && params.rival_empty_space_fraction <= 1.0))
        PCL_TENSOR_THROW (BadArgumentException, "the rival's empty-space margin must be finite and non-negative and its fraction in "
                          "(0, 1], got " << params.rival_empty_space_margin << " and " << params.rival_empty_space_fraction);
      if (!(params.rival_dimension_factor >= 1.0) || !std::isfinite (params.rival_dimension_factor))
        PCL_TENSOR_THROW (BadArgumentException, "the rival's dimension factor must be finite and at least 1, got "
                          << params.rival_dimension_factor);
      if (!(params.rival_icp_max_normal_angle >= 0.0 && params.rival_icp_max_normal_angle <= 180.0))
        PCL_TENSOR_THROW (BadArgumentException, "the rivals' ICP normal angle must be in [0, 180] degrees, got "
                          << params.rival_icp_max_normal_angle);
    }

    pcl::PointCloud<pcl::TensorDescriptor>::Ptr
    computeViewTensors (const PreparedScan& scan, const ObjectDimensions& dims, const TensorRegistrationParams& params)
    {
      detail::ViewTensorEstimation estimation;
      detail::configureViewEstimation (estimation, scan, dims, params);
      pcl::PointCloud<pcl::TensorDescriptor>::Ptr tensors (new pcl::PointCloud<pcl::TensorDescriptor>);
      estimation.computeOrThrow (*tensors);
      return tensors;
    }
  }
}
