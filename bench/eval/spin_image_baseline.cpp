/*
 * pcl_tensor evaluation: the spin-image comparison of Section 8 (Fig. 20).
 */
#include "spin_image_baseline.h"

#include <pcl/features/spin_image.h>
#include <pcl/features/impl/spin_image.hpp>
#include <pcl/registration/correspondence_rejection_tensor_verification.h>
#include <pcl/registration/transformation_estimation_svd.h>

#include <algorithm>
#include <cmath>

namespace pcl_tensor_eval
{
  SpinImageView
  computeSpinImages (const pcl::ScanMesh& mesh, double bin_size, const SpinImageParams& params)
  {
    SpinImageView view;
    for (const auto& p : *mesh.cloud)
      if (std::isfinite (p.normal_x) && p.getNormalVector3fMap ().squaredNorm () > 0.5f)
        view.points->push_back (p);
    // The input and the support surface are the same points, so PCL's normals match both (see the
    // attention note of pcl::SpinImageEstimation).
    pcl::SpinImageEstimation<pcl::PointNormal, pcl::PointNormal, SpinImage> estimation (
        kSpinImageWidth, std::cos (params.support_angle_deg * M_PI / 180.0), 0);
    estimation.setInputCloud (view.points);
    estimation.setInputNormals (view.points);
    estimation.setRadiusSearch (bin_size * kSpinImageWidth);
    estimation.compute (*view.images);
    return view;
  }

  double
  spinImageCorrelation (const SpinImage& a, const SpinImage& b)
  {
    constexpr int n = 153;
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    for (int i = 0; i < n; ++i)
    {
      sa += a.histogram[i];
      sb += b.histogram[i];
      saa += a.histogram[i] * a.histogram[i];
      sbb += b.histogram[i] * b.histogram[i];
      sab += a.histogram[i] * b.histogram[i];
    }
    const double va = n * saa - sa * sa, vb = n * sbb - sb * sb;
    if (!(va > 0.0) || !(vb > 0.0))
      return 0.0;  // an empty or constant image correlates with nothing
    return (n * sab - sa * sb) / std::sqrt (va * vb);
  }

  std::vector<SpinImageMatch>
  matchSpinImages (const SpinImageView& model, const SpinImageView& scene)
  {
    std::vector<SpinImageMatch> matches;
    for (std::size_t s = 0; s < scene.images->size (); ++s)
    {
      SpinImageMatch best;
      best.scene = static_cast<int> (s);
      for (std::size_t m = 0; m < model.images->size (); ++m)
      {
        const double c = spinImageCorrelation ((*scene.images)[s], (*model.images)[m]);
        if (c > best.correlation)
        {
          best.correlation = c;
          best.model = static_cast<int> (m);
        }
      }
      if (best.model >= 0)
        matches.push_back (best);
    }
    std::sort (matches.begin (), matches.end (),
               [] (const SpinImageMatch& a, const SpinImageMatch& b) { return a.correlation > b.correlation; });
    return matches;
  }

  namespace
  {
    double
    angleDeg (const Eigen::Vector3f& a, const Eigen::Vector3f& b)
    {
      return std::acos (std::clamp (static_cast<double> (a.dot (b)), -1.0, 1.0)) * 180.0 / M_PI;
    }

    /** Johnson and Hebert's geometric consistency of two correspondences. */
    bool
    consistent (const SpinImageMatch& a, const SpinImageMatch& b, const SpinImageView& model, const SpinImageView& scene,
                double slack, const SpinImageParams& params)
    {
      const auto& ms = (*model.points)[a.model];
      const auto& mt = (*model.points)[b.model];
      const auto& ss = (*scene.points)[a.scene];
      const auto& st = (*scene.points)[b.scene];
      const double dm = (ms.getVector3fMap () - mt.getVector3fMap ()).norm ();
      const double ds = (ss.getVector3fMap () - st.getVector3fMap ()).norm ();
      if (a.model == b.model || a.scene == b.scene || std::abs (dm - ds) > params.consistency_fraction * 0.5 * (dm + ds) + slack)
        return false;
      const double angle_m = angleDeg (ms.getNormalVector3fMap (), mt.getNormalVector3fMap ());
      const double angle_s = angleDeg (ss.getNormalVector3fMap (), st.getNormalVector3fMap ());
      return std::abs (angle_m - angle_s) <= params.consistency_angle_deg;
    }

    /** The rigid transform of a group of correspondences (scene -> model), least squares. */
    Eigen::Matrix4f
    groupTransform (const std::vector<SpinImageMatch>& group, const SpinImageView& model, const SpinImageView& scene)
    {
      pcl::Correspondences correspondences;
      for (const SpinImageMatch& g : group)
        correspondences.emplace_back (g.scene, g.model, static_cast<float> (1.0 - g.correlation));
      pcl::registration::TransformationEstimationSVD<pcl::PointNormal, pcl::PointNormal> svd;
      Eigen::Matrix4f t;
      svd.estimateRigidTransformation (*scene.points, *model.points, correspondences, t);
      return t;
    }
  }

  SpinImageResult
  registerSpinImages (const EvalView& model, const SpinImageView& model_images, const EvalView& scene,
                      const SpinImageView& scene_images, const pcl::ObjectDimensions& dims,
                      const pcl::registration::TensorRegistrationParams& tensor_params, const SpinImageParams& params)
  {
    SpinImageResult result;
    std::vector<SpinImageMatch> matches = matchSpinImages (model_images, scene_images);
    if (matches.size () > static_cast<std::size_t> (params.candidates))
      matches.resize (params.candidates);
    pcl::registration::CorrespondenceRejectorTensorVerification verification;
    setUpVerification (verification, model, scene, dims, tensor_params);
    // Slack for vertex placement: the reduced meshes' vertices sit a few fine d_res apart at best.
    const double slack = 2.0 * verification.getResolution ();
    for (const SpinImageMatch& seed : matches)
    {
      if (result.hypotheses >= static_cast<std::size_t> (params.max_hypotheses))
        break;
      std::vector<SpinImageMatch> group{seed};
      for (const SpinImageMatch& other : matches)
        if (consistent (seed, other, model_images, scene_images, slack, params))
          group.push_back (other);
      if (group.size () < 3)
        continue;
      ++result.hypotheses;
      pcl::registration::TensorVerificationResult verified;
      if (verification.verify (groupTransform (group, model_images, scene_images), verified))
      {
        result.registered = true;
        result.transform = verified.transform;
        break;
      }
    }
    return result;
  }
}
