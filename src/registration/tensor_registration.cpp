/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/registration/impl/tensor_registration.hpp>
#include "tensor_hypothesis_search.h"
#include "../common/parallel_for.h"

#include <pcl/common/time.h>
#include <pcl/point_types.h>

namespace pcl
{
  namespace registration
  {
    namespace detail
    {
      namespace
      {
        /** The side's view, prepared from its cloud (centred on it) when it was not given. */
        TensorView::ConstPtr
        viewOf (const RegistrationSide& side, const TensorRegistrationParams& params)
        {
          if (side.view)
            return side.view;
          if (!side.cloud)
            PCL_TENSOR_THROW (BadArgumentException, "TensorRegistration: a side has neither a view nor a cloud");
          return prepareTensorView (*side.cloud, side.viewpoint, params.preparation);
        }
      }

      TensorRegistrationReport
      registerViewPair (const RegistrationSide& model_side, const RegistrationSide& scene_side, const ObjectDimensions* known,
                        const TensorRegistrationParams& params, const HypothesisAcceptor& accept, const Eigen::Matrix4f* guess,
                        unsigned threads)
      {
        pcl::StopWatch total, watch;
        TensorRegistrationReport report;
        const RegistrationSide* sides[2] = {&model_side, &scene_side};
        TensorView::ConstPtr views[2];
        pcl::detail::parallelFor (2, threads, [&] (std::size_t k) { views[k] = viewOf (*sides[k], params); });
        const TensorView::ConstPtr& model = views[0];
        const TensorView::ConstPtr& scene = views[1];
        report.timings.prepare_ms = watch.getTime ();
        const ObjectDimensions dims = known ? *known
            : computeObjectDimensions<pcl::PointNormal> ({model->scan->fine.cloud.get (), scene->scan->fine.cloud.get ()});
        Eigen::Matrix4f centred_guess;
        if (guess)
          centred_guess = betweenCentredMeshes (*guess, *model, *scene);
        searchTensorViews (*model, *scene, dims, params, accept, guess ? &centred_guess : nullptr, report);
        if (report.registered || report.ambiguous)
          report.verification.transform = betweenViewFrames (report.verification.transform, *model, *scene);
        if (report.registered)
          report.transform = report.verification.transform;
        if (report.ambiguous)
          report.rival_transform = betweenViewFrames (report.rival_transform, *model, *scene);
        report.timings.total_ms = total.getTime ();
        return report;
      }
    }
  }
}

PCL_INSTANTIATE_TensorRegistration (pcl::PointXYZ, pcl::PointXYZ)
PCL_INSTANTIATE_TensorRegistration (pcl::PointNormal, pcl::PointNormal)
PCL_INSTANTIATE_TensorRegistration (pcl::PointXYZRGB, pcl::PointXYZRGB)
