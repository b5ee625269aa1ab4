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
        // The search works on the centred meshes; the caller's acceptor judges poses between its views.
        HypothesisAcceptor accept_between_views;
        if (accept)
          accept_between_views = [&] (const TensorVerificationResult& local) {
            TensorVerificationResult between_views = local;
            between_views.transform = betweenViewFrames (local.transform, *model, *scene);
            return accept (between_views);
          };
        searchTensorViews (*model, *scene, dims, params, accept_between_views, guess ? &centred_guess : nullptr, report);
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

    TensorRegistrationReport
    registerTensorViews (const TensorView::ConstPtr& model, const TensorView::ConstPtr& scene, const ObjectDimensions& dims,
                         const TensorRegistrationParams& params, const HypothesisAcceptor& accept)
    {
      if (!model || !scene)
        PCL_TENSOR_THROW (BadArgumentException, "registerTensorViews needs two views");
      detail::RegistrationSide model_side, scene_side;
      model_side.view = model;
      scene_side.view = scene;
      return detail::registerViewPair (model_side, scene_side, &dims, params, accept, nullptr, 1);
    }
  }
}

PCL_INSTANTIATE_TensorRegistration (pcl::PointXYZ, pcl::PointXYZ)
PCL_INSTANTIATE_TensorRegistration (pcl::PointNormal, pcl::PointNormal)
PCL_INSTANTIATE_TensorRegistration (pcl::PointXYZRGB, pcl::PointXYZRGB)
