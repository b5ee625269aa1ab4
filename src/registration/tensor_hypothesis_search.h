/*
 * pcl_tensor: the hypothesis search of pairwise registration (private to the library).
 */
#pragma once

#include <pcl/registration/tensor_registration_params.h>
#include <pcl/registration/tensor_registration_report.h>
#include <pcl/registration/tensor_view.h>

namespace pcl
{
  namespace registration
  {
    namespace detail
    {
      /** \brief Register \a scene to \a model, both prepared, with D = \a dims: match (Section 4), then
        * verify hypotheses in order until one passes local verification (Section 4.1) and \a accept, if
        * given (Fig. 7); then, when none settled the pair, the matches under t_r or t_c over the second
        * round's thresholds (TensorRegistrationParams::fallback_overlap_threshold). The scene's tensors
        * are computed in params.scene_tensor_batches batches when \a scene has none, and the model's when
        * \a model has none. With \a guess (between the centred meshes), it is verified first and taken
        * when it passes.
        * \param[in,out] report filled in, transforms between the centred meshes; its preparation time
        * is left as it is
        */
      void
      searchTensorViews (const TensorView& model, const TensorView& scene, const ObjectDimensions& dims,
                         const TensorRegistrationParams& params, const HypothesisAcceptor& accept,
                         const Eigen::Matrix4f* guess, TensorRegistrationReport& report);
    }
  }
}
