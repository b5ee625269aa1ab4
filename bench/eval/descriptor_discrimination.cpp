/*
 * pcl_tensor evaluation: discriminating power of tensors against spin images (Section 8, Fig. 21).
 */
#include "descriptor_discrimination.h"

#include <pcl/common/scan_mesh.h>
#include <pcl/features/tensor.h>
#include <pcl/registration/correspondence_estimation_tensor.h>

#include <algorithm>
#include <random>

namespace pcl_tensor_eval
{
  namespace
  {
    /** The bin size of both descriptors: the resolution of the pair's reduced meshes. */
    double
    binSize (const EvalView& model, const EvalView& scene)
    {
      return 0.5 * (pcl::meshResolution (model.prepared->reduced) + pcl::meshResolution (scene.prepared->reduced));
    }

    /** \a count of \a n indices, drawn without replacement, sorted. */
    std::vector<std::size_t>
    draw (std::size_t n, std::size_t count, std::mt19937& rng)
    {
      std::vector<std::size_t> order (n);
      for (std::size_t i = 0; i < n; ++i)
        order[i] = i;
      std::shuffle (order.begin (), order.end (), rng);
      order.resize (std::min (n, count));
      std::sort (order.begin (), order.end ());
      return order;
    }

    template <typename CloudT>
    typename CloudT::Ptr
    subset (const CloudT& cloud, const std::vector<std::size_t>& keep)
    {
      typename CloudT::Ptr out (new CloudT);
      for (std::size_t i : keep)
        out->push_back (cloud[i]);
      return out;
    }

    pcl::PointCloud<pcl::TensorDescriptor>::Ptr
    sectionEightTensors (const EvalView& view, const pcl::ObjectDimensions& dims, double bin_size,
                         const pcl::registration::TensorRegistrationParams& tensor_params, const DiscriminationParams& params,
                         std::mt19937& rng)
    {
      pcl::TensorEstimation<pcl::PointNormal, pcl::PointNormal, pcl::TensorDescriptor> estimation;
      estimation.setInputCloud (view.prepared->reduced.cloud);
      estimation.setInputNormals (view.prepared->reduced.cloud);
      estimation.setPolygons (view.prepared->reduced.polygons);
      estimation.setObjectDimensions (dims);  // pairing distances of Eq. 2
      estimation.setBinSize (bin_size);       // Section 8: bin size = mesh resolution
      estimation.setGridSize (params.tensor_grid);
      estimation.setPartnersPerVertex (tensor_params.partners_per_vertex);
      estimation.setMinNormalAngle (tensor_params.min_normal_angle);
      pcl::PointCloud<pcl::TensorDescriptor> all;
      estimation.computeOrThrow (all);
      return subset (all, draw (all.size (), static_cast<std::size_t> (params.descriptors), rng));
    }

    double
    displacementBins (const Eigen::Affine3d& truth, const Eigen::Vector3f& scene, const Eigen::Vector3f& model, double bin)
    {
      return (truth * scene.cast<double> () - model.cast<double> ()).norm () / bin;
    }
  }

  DiscriminationErrors
  measureDiscrimination (const EvalView& model, const EvalView& scene, const pcl::ObjectDimensions& dims,
                         const pcl::registration::TensorRegistrationParams& tensor_params, const DiscriminationParams& params)
  {
    std::mt19937 rng (params.seed);
    const double bin = binSize (model, scene);
    const Eigen::Affine3d truth = groundTruth (model, scene);
    DiscriminationErrors errors;

    pcl::registration::CorrespondenceEstimationTensor matcher = tensorMatcher (tensor_params);
    matcher.setInputTarget (sectionEightTensors (model, dims, bin, tensor_params, params, rng));
    matcher.setInputSource (sectionEightTensors (scene, dims, bin, tensor_params, params, rng));
    pcl::Correspondences correspondences;
    matcher.determineCorrespondences (correspondences);  // best first
    const auto& model_tensors = *matcher.getInputTarget ();
    const auto& scene_tensors = *matcher.getInputSource ();
    for (const auto& match : matcher.getMatches ())
    {
      if (errors.tensor_bins.size () >= static_cast<std::size_t> (params.best_matches))
        break;
      errors.tensor_bins.push_back (displacementBins (truth, scene_tensors[match.scene].getVector3fMap (),
                                                      model_tensors[match.model].getVector3fMap (), bin));
    }

    SpinImageParams spin_params;
    SpinImageView model_images = computeSpinImages (model.prepared->reduced, bin, spin_params);
    SpinImageView scene_images = computeSpinImages (scene.prepared->reduced, bin, spin_params);
    for (SpinImageView* v : {&model_images, &scene_images})
    {
      const auto keep = draw (v->images->size (), static_cast<std::size_t> (params.descriptors), rng);
      v->points = subset (*v->points, keep);
      v->images = subset (*v->images, keep);
    }
    for (const SpinImageMatch& match : matchSpinImages (model_images, scene_images))
    {
      if (errors.spin_bins.size () >= static_cast<std::size_t> (params.best_matches))
        break;
      errors.spin_bins.push_back (displacementBins (truth, (*scene_images.points)[match.scene].getVector3fMap (),
                                                    (*model_images.points)[match.model].getVector3fMap (), bin));
    }
    return errors;
  }
}
