/*
 * pcl_tensor: the pipeline's components set from TensorRegistrationParams (private to the library).
 */
#pragma once

#include <pcl/features/tensor.h>
#include <pcl/registration/correspondence_estimation_tensor.h>
#include <pcl/registration/correspondence_rejection_tensor_verification.h>
#include <pcl/registration/tensor_registration_params.h>
#include <pcl/registration/tensor_view.h>

namespace pcl
{
  namespace registration
  {
    namespace detail
    {
      using ViewTensorEstimation = pcl::TensorEstimation<pcl::PointNormal, pcl::PointNormal, pcl::TensorDescriptor>;

      /** The settings of \a params that TensorEstimation takes; its setters check them. */
      void
      configureEstimation (ViewTensorEstimation& estimation, const TensorRegistrationParams& params);

      /** \a estimation set to compute \a scan's tensors (its reduced mesh) with Eqs. 2-3 from \a dims. */
      void
      configureViewEstimation (ViewTensorEstimation& estimation, const PreparedScan& scan, const ObjectDimensions& dims,
                               const TensorRegistrationParams& params);

      /** The matcher's thresholds, index and order from \a params. */
      void
      configureMatcher (CorrespondenceEstimationTensor& matcher, const TensorRegistrationParams& params);

      /** The verifier's views (meshes and tensors), D and thresholds. */
      void
      configureVerifier (CorrespondenceRejectorTensorVerification& verifier, const TensorView& model,
                         const pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr& scene_tensors, const TensorView& scene,
                         const ObjectDimensions& dims, const TensorRegistrationParams& params);
    }
  }
}
