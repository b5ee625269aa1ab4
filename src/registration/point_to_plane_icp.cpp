/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/registration/point_to_plane_icp.h>
#include <pcl/common/tensor_exceptions.h>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <vector>

namespace pcl
{
  namespace registration
  {
    namespace
    {
      /** One linearised point-to-plane step: the 6-vector (rotation, translation) in double. */
      struct Step
      {
        Eigen::Matrix<double, 6, 1> x = Eigen::Matrix<double, 6, 1>::Zero ();
        std::size_t pairs = 0;
        double rms = 0.0;
        bool solved = false;
      };

      Step
      solveStep (const pcl::PointCloud<pcl::PointNormal>& source, std::size_t stride, const pcl::PointCloud<pcl::PointNormal>& target,
                 const pcl::BoundedNearestSearch& search, const Eigen::Matrix4f& t, double max_distance,
                 double min_normal_cosine, std::vector<std::int32_t>& hints)
      {
        Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Zero ();
        Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero ();
        const float radius = static_cast<float> (max_distance);
        // At pi every pair is used, exactly opposite normals too (a rounded cosine could drop them).
        const bool check_normals = min_normal_cosine > -1.0;
        Step step;
        double sum2 = 0.0;
        for (std::size_t i = 0; i < source.size (); i += stride)
        {
          const auto& p = source[i];
          const Eigen::Vector3f q = (t * p.getVector4fMap ()).head<3> ();
          float d2;
          const int index = search.nearest (q, radius, d2, hints[i]);
          if (index < 0)
            continue;
          const auto& m = target[index];
          const Eigen::Vector3d n = m.getNormalVector3fMap ().cast<double> ();
          if (!n.allFinite () || n.squaredNorm () == 0.0)
            continue;  // no tangent plane: a vertex on no face, or a cloud without normals
          if (check_normals)
          {
            const Eigen::Vector3f ns = t.topLeftCorner<3, 3> () * p.getNormalVector3fMap ();
            if (ns.allFinite () && ns.squaredNorm () > 0.0f && ns.cast<double> ().dot (n) < min_normal_cosine * ns.norm () * n.norm ())
              continue;  // another face of the target: its plane would pull the pose off
          }
          const Eigen::Vector3d s = q.cast<double> ();
          const double r = (s - m.getVector3fMap ().cast<double> ()).dot (n);
          Eigen::Matrix<double, 6, 1> j;
          j << s.cross (n), n;
          a.noalias () += j * j.transpose ();
          b.noalias () -= j * r;
          sum2 += r * r;
          ++step.pairs;
        }
        if (step.pairs < 6)
          return step;
        const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt (a);
        if (ldlt.info () != Eigen::Success)
          return step;
        step.x = ldlt.solve (b);
        step.rms = std::sqrt (sum2 / static_cast<double> (step.pairs));
        step.solved = step.x.allFinite ();
        return step;
      }
    }

    namespace
    {
      /** One stage: iterate at one pairing distance from \a result's pose, updating it in place;
        * \a hints: each source point's last partner, so that the next search starts from it. */
      void
      iterate (const pcl::PointCloud<pcl::PointNormal>& source, std::size_t stride, const pcl::PointCloud<pcl::PointNormal>& target,
               const pcl::BoundedNearestSearch& search, const PointToPlaneIcpParams& params, double max_distance,
               double tolerance, std::vector<std::int32_t>& hints, PointToPlaneIcpResult& result)
      {
        // Pair counts are scaled to the whole source, so that a subsample whose points all pair counts as all of them.
        const std::size_t sampled = (source.size () + stride - 1) / stride;
        for (int it = 0; it < params.max_iterations; ++it)
        {
          const Step step = solveStep (source, stride, target, search, result.transform, max_distance,
                                       std::cos (params.max_normal_angle), hints);
          result.pairs = sampled ? step.pairs * source.size () / sampled : 0;
          result.rms = step.rms;
          if (!step.solved)
            break;
          // The small rotation of the linearisation, applied as an exact rotation about its axis.
          const Eigen::Vector3d w = step.x.head<3> ();
          Eigen::Affine3d update = Eigen::Affine3d::Identity ();
          if (w.norm () > 0.0)
            update.linear () = Eigen::AngleAxisd (w.norm (), w.normalized ()).toRotationMatrix ();
          update.translation () = step.x.tail<3> ();
          result.transform = (update.matrix () * result.transform.cast<double> ()).cast<float> ();
          ++result.iterations;
          if (w.norm () < tolerance * params.min_rotation && step.x.tail<3> ().norm () <= tolerance * params.min_translation)
            break;
        }
      }
    }

    PointToPlaneIcpResult
    pointToPlaneIcp (const pcl::PointCloud<pcl::PointNormal>& source, const pcl::PointCloud<pcl::PointNormal>& target,
                     const pcl::BoundedNearestSearch& search, const Eigen::Matrix4f& initial,
                     const PointToPlaneIcpParams& params)
    {
      if (!(params.max_distance > 0.0) || params.max_iterations < 0 || !(params.final_distance >= 0.0)
          || !(params.coarse_stage_tolerance >= 1.0) || !std::isfinite (params.coarse_stage_tolerance) || params.coarse_stage_step < 1
          || !(params.max_normal_angle >= 0.0 && params.max_normal_angle <= M_PI))
        PCL_TENSOR_THROW (BadArgumentException, "ICP needs a positive pairing distance, a non-negative final distance, "
                          "a non-negative iteration count, a finite coarse-stage tolerance of at least 1, a "
                          "coarse-stage step of at least 1 and a normal angle in [0, pi]");
      PointToPlaneIcpResult result;
      result.transform = initial;
      // The pairing distances of the stages, halving from max_distance down to final_distance.
      std::vector<double> stages{params.max_distance};
      std::vector<std::int32_t> hints (source.size (), -1);
      while (params.final_distance > 0.0 && stages.back () > params.final_distance)
        stages.push_back (std::max (0.5 * stages.back (), params.final_distance));
      for (std::size_t s = 0; s < stages.size (); ++s)
      {
        const bool last = s + 1 == stages.size ();
        if (s > 0 && result.pairs < params.min_pairs)
        {
          result.stopped_early = true;
          break;
        }
        std::size_t stride = 1;
        for (std::size_t k = s + 1; k < stages.size (); ++k)
          stride *= static_cast<std::size_t> (params.coarse_stage_step);
        // A subsample too small to solve for six unknowns would end the refinement for nothing.
        stride = std::max<std::size_t> (1, std::min (stride, source.size () / 64));
        iterate (source, stride, target, search, params, stages[s], last ? 1.0 : params.coarse_stage_tolerance, hints, result);
        result.stage_transforms.push_back (result.transform);
        if (!last && params.continue_after_stage && !params.continue_after_stage (s, result.transform))
        {
          result.abandoned = true;
          break;
        }
      }
      return result;
    }
  }
}
