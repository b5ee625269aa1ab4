/*
 * pcl_tensor evaluation: views of one object with ground-truth poses, prepared once for all pairs.
 */
#pragma once

#include <pcl/common/object_dimensions.h>
#include <pcl/common/scan_mesh.h>
#include <pcl/features/tensor_descriptor.h>
#include <pcl/registration/correspondence_rejection_tensor_verification.h>
#include <pcl/registration/tensor_registration.h>
#include <pcl/simulation/synthetic_views.h>
#include <pcl/simulation/view_set.h>
#include <pcl/surface/scan_preparation.h>

#include <Eigen/Geometry>

#include <memory>
#include <string>
#include <vector>

namespace pcl_tensor_eval
{
  /** \brief One range image of an evaluation set: the raw cloud, its sensor, its ground-truth pose,
    * and (after prepareViews()) its meshes and tensors.
    */
  struct EvalView
  {
    std::string name;
    /** Raw points in the view's own frame (organized, NaN holes allowed). */
    pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
    pcl::ScanViewpoint viewpoint;
    /** Ground truth: maps the view's points into the common frame. */
    Eigen::Affine3d pose = Eigen::Affine3d::Identity ();
    std::size_t finite_points = 0;
    /** Filled by prepareViews(). */
    std::shared_ptr<const pcl::PreparedScan> prepared;
    pcl::PointCloud<pcl::TensorDescriptor>::ConstPtr tensors;
    double prepare_ms = 0.0, tensors_ms = 0.0;
  };

  using EvalViews = std::vector<EvalView, Eigen::aligned_allocator<EvalView>>;

  /** \brief Every scan of a Stanford .conf file (e.g. bun.conf), in file order, with its pose.
    * \throw pcl::IOException when the .conf or a scan cannot be read
    */
  EvalViews
  loadStanfordViews (const std::string& conf_path);

  /** \brief The synthetic views of \a mesh from the 26 default directions (Sections 6 and 7.1). */
  EvalViews
  makeSyntheticViews (const pcl::ScanMesh& mesh, const pcl::SyntheticViewParams& params);

  /** \brief The synthetic views of \a mesh from \a directions (e.g. pcl::makeRingViewDirections()). */
  EvalViews
  makeSyntheticViews (const pcl::ScanMesh& mesh, const pcl::SyntheticViewParams& params, const pcl::ViewDirections& directions);

  /** \brief Prepare every view (M_i, M'_i), compute D from all of them (Eq. 1), then each view's
    * tensors once: what a multiview session does before registering pairs.
    * \return D
    */
  pcl::ObjectDimensions
  prepareViews (EvalViews& views, const pcl::registration::TensorRegistrationParams& params);

  /** \brief Ground truth of a pair: the transform taking scene points into the model's frame,
    * pose(model)^-1 * pose(scene).
    */
  inline Eigen::Affine3d
  groundTruth (const EvalView& model, const EvalView& scene)
  {
    return model.pose.inverse () * scene.pose;
  }

  /** \brief Print D and one line per prepared view (points, d_res, tensors, times). */
  void
  printViews (const EvalViews& views, const pcl::ObjectDimensions& dims);

  /** \brief The view as TensorRegistration takes it: its meshes and, with \a tensors, its tensors. */
  pcl::registration::TensorView::Ptr
  tensorView (const EvalView& view, bool tensors = true);

  /** \brief A tensor matcher set from \a params, as TensorRegistration sets its own. */
  pcl::registration::CorrespondenceEstimationTensor
  tensorMatcher (const pcl::registration::TensorRegistrationParams& params);

  /** \brief Local verification of \a scene against \a model with D = \a dims, as TensorRegistration sets it. */
  void
  setUpVerification (pcl::registration::CorrespondenceRejectorTensorVerification& verification, const EvalView& model,
                     const EvalView& scene, const pcl::ObjectDimensions& dims,
                     const pcl::registration::TensorRegistrationParams& params);

  /** \brief All pairs (i < j) of \a n views, model = i, scene = j. */
  std::vector<std::pair<int, int>>
  allPairs (int n);
}
