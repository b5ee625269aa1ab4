/*
 * pcl_tensor evaluation: multiview registration scored against ground-truth poses (issue 6).
 */
#include "multiview_evaluation.h"

#include <pcl/common/transforms.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/registration/lum.h>
#include <pcl/registration/registration_error.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl_tensor_eval
{
  namespace
  {
    /** Errors of G * estimate(i) against GT(i) for the registered views; NaN for the others. */
    std::vector<ViewPoseError>
    errorsInFrame (const EvalViews& views, const pcl::registration::ViewPoses& estimates, const std::vector<bool>& registered,
                   const Eigen::Affine3d& frame, double resolution)
    {
      std::vector<ViewPoseError> errors (views.size ());
      for (std::size_t i = 0; i < views.size (); ++i)
      {
        if (!registered[i])
        {
          errors[i].rotation_deg = errors[i].translation_res = std::numeric_limits<double>::quiet_NaN ();
          continue;
        }
        const pcl::RegistrationError e = pcl::registrationError (frame * estimates[i], views[i].pose, resolution);
        errors[i].rotation_deg = e.rotation_deg;
        errors[i].translation_res = e.translation_resolutions;
      }
      return errors;
    }
  }

  std::vector<ViewPoseError>
  poseErrors (const EvalViews& views, const pcl::registration::ViewPoses& estimates, const std::vector<bool>& registered,
              int reference, double resolution)
  {
    if (reference < 0)
      return errorsInFrame (views, estimates, std::vector<bool> (views.size (), false), Eigen::Affine3d::Identity (), resolution);
    return errorsInFrame (views, estimates, registered, views[reference].pose, resolution);
  }

  std::vector<ViewPoseError>
  poseErrorsInBestFrame (const EvalViews& views, const pcl::registration::ViewPoses& estimates,
                         const std::vector<bool>& registered, double resolution)
  {
    std::vector<const pcl::PointCloud<pcl::PointXYZ>*> clouds;
    pcl::registration::ViewPoses truth;
    for (std::size_t i = 0; i < views.size (); ++i)
    {
      clouds.push_back (registered[i] ? views[i].cloud.get () : nullptr);
      truth.push_back (views[i].pose);
    }
    const bool any = std::count (registered.begin (), registered.end (), true) > 0;
    const Eigen::Affine3d frame = any ? pcl::bestFitCommonFrame (clouds, estimates, truth) : Eigen::Affine3d::Identity ();
    return errorsInFrame (views, estimates, registered, frame, resolution);
  }

  namespace
  {
    double
    median (std::vector<double> v)
    {
      if (v.empty ())
        return std::numeric_limits<double>::quiet_NaN ();
      std::sort (v.begin (), v.end ());
      const std::size_t n = v.size ();
      return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    }
  }

  PoseErrorSummary
  summarize (const std::vector<ViewPoseError>& errors)
  {
    PoseErrorSummary s;
    std::vector<double> r, t;
    for (const auto& e : errors)
      if (std::isfinite (e.rotation_deg))
      {
        r.push_back (e.rotation_deg);
        t.push_back (e.translation_res);
      }
    s.views = r.size ();
    if (r.empty ())
      return s;
    s.max_rotation_deg = *std::max_element (r.begin (), r.end ());
    s.max_translation_res = *std::max_element (t.begin (), t.end ());
    s.median_rotation_deg = median (r);
    s.median_translation_res = median (t);
    return s;
  }

  std::vector<pcl::registration::MultiviewInput>
  multiviewInputs (const EvalViews& views)
  {
    std::vector<pcl::registration::MultiviewInput> inputs;
    for (const auto& v : views)
      inputs.push_back ({v.name, v.cloud, v.viewpoint, nullptr});
    return inputs;
  }

  namespace
  {
    /** An evenly spaced sample of a view's fine points. */
    pcl::PointCloud<pcl::PointXYZ>::Ptr
    sampleCloud (const pcl::PointCloud<pcl::PointNormal>& fine, int n)
    {
      pcl::PointCloud<pcl::PointXYZ>::Ptr out (new pcl::PointCloud<pcl::PointXYZ>);
      const std::size_t count = std::min (fine.size (), static_cast<std::size_t> (n));
      for (std::size_t k = 0; k < count; ++k)
      {
        const auto& p = fine[k * fine.size () / count];
        out->push_back (pcl::PointXYZ (p.x, p.y, p.z));
      }
      return out;
    }
  }

  pcl::registration::ViewPoses
  lumGlobalRegistration (const pcl::registration::MultiviewRegistrationResult& result, int rounds, int sample_points,
                         double max_distance_res)
  {
    // LUM fixes its first vertex: the reference view goes first.
    std::vector<int> order{result.reference};
    for (std::size_t i = 0; i < result.views.size (); ++i)
      if (result.views[i].registered && static_cast<int> (i) != result.reference)
        order.push_back (static_cast<int> (i));
    std::vector<int> vertex_of (result.views.size (), -1);
    pcl::registration::LUM<pcl::PointXYZ> lum;
    std::vector<pcl::PointCloud<pcl::PointXYZ>::Ptr> clouds;
    // As PCL's own lum tool does: the clouds go in already in the common frame, with zero poses, and
    // LUM's poses are corrections of the pairwise ones. (Given the pairwise poses as 6-vectors
    // instead, LUM's Euler-angle linearisation diverged on the turntable: 177 degrees.)
    for (const int i : order)
    {
      clouds.push_back (sampleCloud (*result.views[i].prepared->fine.cloud, sample_points));
      pcl::transformPointCloud (*clouds.back (), *clouds.back (), result.views[i].pairwise_pose.cast<float> ());
      vertex_of[i] = static_cast<int> (lum.addPointCloud (clouds.back ()));
    }
    const float max_d2 = static_cast<float> (std::pow (max_distance_res * result.resolution, 2));
    for (int round = 0; round < rounds; ++round)
    {
      for (const auto& p : result.pairs)
      {
        const int a = vertex_of[p.first], b = vertex_of[p.second];
        const auto source = lum.getTransformedCloud (a);
        const auto target = lum.getTransformedCloud (b);
        pcl::KdTreeFLANN<pcl::PointXYZ> tree;
        tree.setInputCloud (target);
        pcl::CorrespondencesPtr corrs (new pcl::Correspondences);
        pcl::Indices index (1);
        std::vector<float> d2 (1);
        for (std::size_t k = 0; k < source->size (); ++k)
          if (tree.nearestKSearch ((*source)[k], 1, index, d2) == 1 && d2[0] <= max_d2)
            corrs->emplace_back (static_cast<int> (k), index[0], d2[0]);
        if (corrs->size () >= 3)
          lum.setCorrespondences (a, b, corrs);
      }
      lum.setMaxIterations (10);
      lum.setConvergenceThreshold (0.0f);
      lum.compute ();
    }
    pcl::registration::ViewPoses poses (result.views.size (), Eigen::Affine3d::Identity ());
    for (std::size_t i = 0; i < result.views.size (); ++i)
      if (vertex_of[i] >= 0)
        poses[i] = lum.getTransformation (vertex_of[i]).cast<double> () * result.views[i].pairwise_pose;
    return poses;
  }
}
