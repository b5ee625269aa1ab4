/*
 * TensorRegistration as a pcl::Registration: the fitness score, the guess, the point types PCL users
 * pass, and views prepared once giving what the clouds give.
 */
#include "test_utils.h"

#include <pcl/common/io.h>
#include <pcl/filters/filter.h>
#include <pcl/registration/correspondence_rejection_tensor_verification.h>
#include <pcl/registration/registration_error.h>
#include <pcl/registration/tensor_registration.h>
#include <pcl/simulation/example_object.h>
#include <pcl/simulation/synthetic_views.h>
#include <pcl/simulation/view_set.h>

#include <limits>

namespace
{
  using pcl::registration::TensorRegistration;
  using Cloud = pcl::PointCloud<pcl::PointXYZ>;

  /** Two views of the built-in object 30 degrees apart, organized 200 x 200 with NaN background. */
  const std::vector<pcl::SyntheticView>&
  pairViews ()
  {
    static const std::vector<pcl::SyntheticView> views = [] {
      pcl::SyntheticViewParams params;
      params.camera.width = params.camera.height = 200;
      return pcl::renderSyntheticViews (pcl::makeExampleObject (), pcl::makeRingViewDirections (2, 30.0), params);
    } ();
    return views;
  }

  Eigen::Affine3d
  truth ()
  {
    return pairViews ()[0].view.pose.inverse () * pairViews ()[1].view.pose;
  }

  template <typename PointT> typename pcl::PointCloud<PointT>::Ptr
  as (const Cloud& cloud)
  {
    typename pcl::PointCloud<PointT>::Ptr out (new pcl::PointCloud<PointT>);
    pcl::copyPointCloud (cloud, *out);
    return out;
  }

  /** Registers view 1 to view 0 from \a model and \a scene clouds of any point type. */
  template <typename PointT> void
  registerPair (TensorRegistration<PointT>& registration, const typename pcl::PointCloud<PointT>::Ptr& model,
                const typename pcl::PointCloud<PointT>::Ptr& scene,
                const Eigen::Matrix4f& guess = Eigen::Matrix4f::Identity ())
  {
    registration.setInputTarget (model);
    registration.setInputSource (scene);
    registration.setTargetViewpoint (pairViews ()[0].view.viewpoint);
    registration.setSourceViewpoint (pairViews ()[1].view.viewpoint);
    pcl::PointCloud<PointT> aligned;
    registration.align (aligned, guess);
  }

  /** The mean squared distance from each finite moved source point to its nearest finite target
    * point, by brute force; the source is moved in float, as Registration moves it. */
  double
  bruteForceFitness (const Cloud& source, const Cloud& target, const Eigen::Matrix4f& t)
  {
    double sum = 0.0;
    std::size_t n = 0;
    for (const auto& p : source)
    {
      if (!pcl::isXYZFinite (p))
        continue;
      const Eigen::Vector4f q = t * Eigen::Vector4f (p.x, p.y, p.z, 1.0f);
      double best = std::numeric_limits<double>::max ();
      for (const auto& r : target)
        if (pcl::isXYZFinite (r))
          best = std::min (best, (q.head<3> ().cast<double> () - r.getVector3fMap ().cast<double> ()).squaredNorm ());
      sum += best;
      ++n;
    }
    return sum / static_cast<double> (n);
  }
}

TEST (TensorRegistrationPcl, FitnessScoreIsTheMeanSquaredDistanceOnOrganizedAndDenseClouds)
{
  const Cloud::Ptr model = pairViews ()[0].view.cloud, scene = pairViews ()[1].view.cloud;
  ASSERT_GT (model->height, 1u);
  ASSERT_FALSE (model->is_dense) << "the organized case needs NaN cells";
  // Organized, NaN cells and all: pcl::Registration's own score aborts on them.
  TensorRegistration<pcl::PointXYZ> organized;
  registerPair<pcl::PointXYZ> (organized, model, scene);
  ASSERT_TRUE (organized.hasConverged ());
  const double expected = bruteForceFitness (*scene, *model, organized.getFinalTransformation ());
  EXPECT_GT (expected, 0.0);
  EXPECT_NEAR (organized.getFitnessScore (), expected, 1e-6 * expected);
  // max_range is compared with the squared distance, as pcl::Registration does: none within 0.
  EXPECT_EQ (organized.getFitnessScore (0.0), std::numeric_limits<double>::max ());

  // Dense: the NaN points removed.
  Cloud::Ptr dense_model (new Cloud), dense_scene (new Cloud);
  pcl::Indices unused;
  pcl::removeNaNFromPointCloud (*model, *dense_model, unused);
  pcl::removeNaNFromPointCloud (*scene, *dense_scene, unused);
  TensorRegistration<pcl::PointXYZ> dense;
  registerPair<pcl::PointXYZ> (dense, dense_model, dense_scene);
  ASSERT_TRUE (dense.hasConverged ());
  const double expected_dense = bruteForceFitness (*dense_scene, *dense_model, dense.getFinalTransformation ());
  EXPECT_NEAR (dense.getFitnessScore (), expected_dense, 1e-6 * expected_dense);
  // A new target is searched anew.
  dense.setInputTarget (dense_scene);
  EXPECT_NEAR (dense.getFitnessScore (), bruteForceFitness (*dense_scene, *dense_scene, dense.getFinalTransformation ()),
               1e-6 * expected_dense);
}

TEST (TensorRegistrationPcl, TheGuessIsIgnoredUnlessItIsToBeVerified)
{
  const Cloud::Ptr model = pairViews ()[0].view.cloud, scene = pairViews ()[1].view.cloud;
  TensorRegistration<pcl::PointXYZ> plain;
  registerPair<pcl::PointXYZ> (plain, model, scene);
  ASSERT_TRUE (plain.hasConverged ());
  const Eigen::Matrix4f turned = (Eigen::Affine3f (Eigen::AngleAxisf (static_cast<float> (M_PI), Eigen::Vector3f::UnitY ())) *
                                  Eigen::Affine3f (truth ().cast<float> ())).matrix ();

  // Ignored by default: a turned guess changes nothing.
  TensorRegistration<pcl::PointXYZ> ignoring;
  registerPair<pcl::PointXYZ> (ignoring, model, scene, turned);
  EXPECT_TRUE (ignoring.getFinalTransformation () == plain.getFinalTransformation ());
  EXPECT_FALSE (ignoring.getReport ().guess_accepted);

  // Verified: the true pose is taken at once; a turned one is refused and the tensors find the pose.
  TensorRegistration<pcl::PointXYZ> verifying;
  verifying.setVerifyGuess (true);
  registerPair<pcl::PointXYZ> (verifying, model, scene, truth ().matrix ().cast<float> ());
  ASSERT_TRUE (verifying.hasConverged ());
  EXPECT_TRUE (verifying.getReport ().guess_accepted);
  EXPECT_EQ (verifying.getReport ().hypotheses_tried, 1u);
  EXPECT_EQ (verifying.getReport ().matches, 0u) << "no tensor matching after a verified guess";
  const double d_res = pairViews ()[0].resolution;
  auto error = pcl::registrationError (Eigen::Affine3d (verifying.getFinalTransformation ().cast<double> ()), truth (), d_res);
  EXPECT_LT (error.rotation_deg, 0.5);
  EXPECT_LT (error.translation_resolutions, 1.0);

  registerPair<pcl::PointXYZ> (verifying, model, scene, turned);
  ASSERT_TRUE (verifying.hasConverged ());
  EXPECT_FALSE (verifying.getReport ().guess_accepted);
  EXPECT_GT (verifying.getReport ().matches, 0u);
  error = pcl::registrationError (Eigen::Affine3d (verifying.getFinalTransformation ().cast<double> ()), truth (), d_res);
  EXPECT_LT (error.rotation_deg, 0.5);
}

TEST (TensorRegistrationPcl, PointNormalAndPointXYZRGBGiveThePointXYZTransform)
{
  const Cloud::Ptr model = pairViews ()[0].view.cloud, scene = pairViews ()[1].view.cloud;
  TensorRegistration<pcl::PointXYZ> xyz;
  registerPair<pcl::PointXYZ> (xyz, model, scene);
  ASSERT_TRUE (xyz.hasConverged ());

  TensorRegistration<pcl::PointNormal> normals;
  registerPair<pcl::PointNormal> (normals, as<pcl::PointNormal> (*model), as<pcl::PointNormal> (*scene));
  EXPECT_TRUE (normals.hasConverged ());
  EXPECT_TRUE (normals.getFinalTransformation () == xyz.getFinalTransformation ());

  auto coloured_scene = as<pcl::PointXYZRGB> (*scene);
  for (auto& p : *coloured_scene)
    p.r = 200, p.g = 10, p.b = 30;
  TensorRegistration<pcl::PointXYZRGB> colour;
  colour.setInputTarget (as<pcl::PointXYZRGB> (*model));
  colour.setInputSource (coloured_scene);
  colour.setTargetViewpoint (pairViews ()[0].view.viewpoint);
  colour.setSourceViewpoint (pairViews ()[1].view.viewpoint);
  pcl::PointCloud<pcl::PointXYZRGB> aligned;
  colour.align (aligned);
  EXPECT_TRUE (colour.hasConverged ());
  EXPECT_TRUE (colour.getFinalTransformation () == xyz.getFinalTransformation ());
  ASSERT_EQ (aligned.size (), coloured_scene->size ());
  EXPECT_EQ (aligned[aligned.size () / 2].r, 200) << "the output keeps the scene's colours";
}

TEST (TensorRegistrationPcl, ViewsPreparedOnceGiveTheTransformOfTheClouds)
{
  const auto& views = pairViews ();
  TensorRegistration<pcl::PointXYZ> from_clouds;
  registerPair<pcl::PointXYZ> (from_clouds, views[0].view.cloud, views[1].view.cloud);
  ASSERT_TRUE (from_clouds.hasConverged ());

  const pcl::registration::TensorRegistrationParams params;
  TensorRegistration<pcl::PointXYZ> from_views;
  from_views.setTargetView (pcl::registration::prepareTensorView (*views[0].view.cloud, views[0].view.viewpoint, params.preparation));
  from_views.setSourceView (pcl::registration::prepareTensorView (*views[1].view.cloud, views[1].view.viewpoint, params.preparation));
  registerPair<pcl::PointXYZ> (from_views, views[0].view.cloud, views[1].view.cloud);
  ASSERT_TRUE (from_views.hasConverged ());
  EXPECT_TRUE (from_views.getFinalTransformation () == from_clouds.getFinalTransformation ());
  EXPECT_EQ (from_views.getReport ().hypotheses_tried, from_clouds.getReport ().hypotheses_tried);
}

TEST (TensorRegistrationPcl, TheRejectorReportsEveryCorrespondenceItExamined)
{
  // getRemainingCorrespondences is the path the pipeline takes: its per-correspondence results hold the
  // stage each hypothesis failed at, and the match details fix each one's pair order.
  const auto& views = pairViews ();
  const pcl::registration::TensorRegistrationParams params;
  const auto model = pcl::registration::prepareTensorView (*views[0].view.cloud, views[0].view.viewpoint, params.preparation);
  const auto scene = pcl::registration::prepareTensorView (*views[1].view.cloud, views[1].view.viewpoint, params.preparation);
  const auto dims = pcl::computeObjectDimensions<pcl::PointNormal> ({model->scan->fine.cloud.get (), scene->scan->fine.cloud.get ()});
  const auto model_tensors = pcl::registration::computeViewTensors (*model->scan, dims, params);
  const auto scene_tensors = pcl::registration::computeViewTensors (*scene->scan, dims, params);
  pcl::registration::CorrespondenceEstimationTensor matcher;
  matcher.setInputSource (scene_tensors);
  matcher.setInputTarget (model_tensors);
  pcl::Correspondences matches, kept;
  matcher.determineCorrespondences (matches);
  ASSERT_GE (matches.size (), 5u);
  matches.resize (5);
  std::vector<pcl::registration::TensorMatch> details (matcher.getMatches ().begin (), matcher.getMatches ().begin () + 5);

  pcl::registration::CorrespondenceRejectorTensorVerification rejector;
  rejector.setModel (model->scan, model_tensors);
  rejector.setScene (scene->scan, scene_tensors);
  rejector.setObjectDimensions (dims);
  rejector.setInputMatches (details);
  rejector.getRemainingCorrespondences (matches, kept);
  ASSERT_EQ (rejector.getResults ().size (), 5u);
  std::size_t passed = 0;
  for (const auto& r : rejector.getResults ())
    passed += r.passed () ? 1 : 0;
  EXPECT_EQ (passed, kept.size ());
  EXPECT_EQ (rejector.getAcceptedTransforms ().size (), kept.size ());
  // Details that do not fit the correspondences are refused.
  rejector.setInputMatches (std::vector<pcl::registration::TensorMatch> (2));
  EXPECT_THROW (rejector.getRemainingCorrespondences (matches, kept), pcl::BadArgumentException);
}
