/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/recorded_pair_registration.h>
#include <pcl/io/tensor_view_cache_key.h>

#include <map>
#include <memory>

namespace pcl
{
  namespace io
  {
    pcl::registration::ViewPairRegistration
    recordedPairRegistration (const std::vector<ViewPairResult>& results, const std::vector<std::string>& view_files,
                              const pcl::registration::ViewPairRegistration& fallback)
    {
      using Report = pcl::registration::TensorRegistrationReport;
      auto recorded = std::make_shared<std::map<std::pair<std::string, std::string>, Report>> ();
      for (const auto& r : results)
        (*recorded)[{r.model, r.scene}] = r.report;
      std::vector<std::string> ids;
      for (const auto& f : view_files)
        ids.push_back (viewIdOf (f));
      return [recorded, ids, fallback] (int model, int scene, const pcl::registration::TensorView::ConstPtr& model_view,
                                        const pcl::registration::TensorView::ConstPtr& scene_view, const ObjectDimensions& dims,
                                        const pcl::registration::TensorRegistrationParams& params) {
        const auto& a = ids.at (model);
        const auto& b = ids.at (scene);
        if (const auto it = recorded->find ({a, b}); it != recorded->end ())
          return reportWithinHypotheses (it->second, params.max_hypotheses);
        if (const auto it = recorded->find ({b, a}); it != recorded->end ())
        {
          Report turned = reportWithinHypotheses (it->second, params.max_hypotheses);
          turned.transform = Eigen::Matrix4f (turned.transform.inverse ());
          turned.rival_transform = Eigen::Matrix4f (turned.rival_transform.inverse ());
          return turned;
        }
        return fallback (model, scene, model_view, scene_view, dims, params);
      };
    }
  }
}
