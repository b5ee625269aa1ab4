/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/registration/pose_conditioning.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <cmath>
#include <vector>

namespace pcl
{
  namespace registration
  {
    namespace
    {
      struct PairedPoint
      {
        Eigen::Vector3d point, normal;
      };

      /** Source points under \a t with their nearest target point's normal, within \a max_distance. */
      std::vector<PairedPoint>
      pairPoints (const pcl::PointCloud<pcl::PointNormal>& source, const pcl::PointCloud<pcl::PointNormal>& target,
                  const pcl::BoundedNearestSearch& search, const Eigen::Matrix4f& t, double max_distance)
      {
        std::vector<PairedPoint> pairs;
        pairs.reserve (source.size ());
        const float radius = static_cast<float> (max_distance);
        for (const auto& p : source)
        {
          const Eigen::Vector3f q = (t * p.getVector4fMap ()).head<3> ();
          float d2;
          const int index = search.nearest (q, radius, d2);
          if (index < 0)
            continue;
          const Eigen::Vector3d n = target[index].getNormalVector3fMap ().cast<double> ();
          if (n.allFinite () && n.squaredNorm () > 0.0)
            pairs.push_back ({q.cast<double> (), n.normalized ()});
        }
        return pairs;
      }
    }

    PoseConditioning
    computePoseConditioning (const pcl::PointCloud<pcl::PointNormal>& source, const pcl::PointCloud<pcl::PointNormal>& target,
                             const pcl::BoundedNearestSearch& search, const Eigen::Matrix4f& t, double max_distance)
    {
      PoseConditioning result;
      const std::vector<PairedPoint> pairs = pairPoints (source, target, search, t, max_distance);
      result.pairs = pairs.size ();
      if (pairs.size () < 6)
        return result;
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero ();
      for (const auto& p : pairs)
        centroid += p.point;
      centroid /= static_cast<double> (pairs.size ());
      Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero ();
      for (const auto& p : pairs)
        covariance.noalias () += (p.point - centroid) * (p.point - centroid).transpose ();
      covariance /= static_cast<double> (pairs.size ());
      result.centroid = centroid;
      result.axes = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> (covariance).eigenvectors ();
      result.radius = std::sqrt (covariance.trace ());
      if (!(result.radius > 0.0))
        return result;
      // Rotations about the centroid, scaled by the radius: the matrix is then free of where the
      // frame's origin is and of the object's size, and its eigenvalues compare across objects.
      Eigen::Matrix<double, 6, 6> information = Eigen::Matrix<double, 6, 6>::Zero ();
      for (const auto& p : pairs)
      {
        Eigen::Matrix<double, 6, 1> row;
        row << (p.point - centroid).cross (p.normal) / result.radius, p.normal;
        information.noalias () += row * row.transpose ();
      }
      information /= static_cast<double> (pairs.size ());
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> solver (information);
      result.eigenvalues = solver.eigenvalues ();
      result.eigenvectors = solver.eigenvectors ();
      const double largest = result.eigenvalues (5);
      result.ratio = largest > 0.0 ? std::max (0.0, result.eigenvalues (0)) / largest : 0.0;
      return result;
    }

    namespace
    {
      /** The rigid motion of the twist (\a omega, \a v) about \a centre (SE(3)'s exponential, \a v the
        * velocity of the centre): a twist that keeps a surface on itself to first order, such as a
        * turn about a cylinder's axis, then keeps it there exactly. */
      Eigen::Matrix4f
      motionAbout (const Eigen::Vector3d& centre, const Eigen::Vector3d& omega, const Eigen::Vector3d& v)
      {
        const double angle = omega.norm ();
        Eigen::Matrix3d r = Eigen::Matrix3d::Identity (), left = Eigen::Matrix3d::Identity ();
        if (angle > 1e-12)
        {
          Eigen::Matrix3d w;
          w << 0.0, -omega.z (), omega.y (), omega.z (), 0.0, -omega.x (), -omega.y (), omega.x (), 0.0;
          r = Eigen::AngleAxisd (angle, omega / angle).toRotationMatrix ();
          left += (1.0 - std::cos (angle)) / (angle * angle) * w + (angle - std::sin (angle)) / (angle * angle * angle) * w * w;
        }
        Eigen::Matrix4d m = Eigen::Matrix4d::Identity ();
        m.topLeftCorner<3, 3> () = r;
        m.topRightCorner<3, 1> () = centre - r * centre + left * v;
        return m.cast<float> ();
      }

      /** Enough pairs to have motions at all: six unknowns, and a common part with some extent. */
      bool
      determinable (const PoseConditioning& conditioning)
      {
        return conditioning.pairs >= 6 && conditioning.radius > 0.0;
      }
    }

    std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>>
    motionPoses (const PoseConditioning& conditioning, const Eigen::Matrix4f& pose, int directions, const std::vector<double>& steps)
    {
      std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>> poses;
      if (!determinable (conditioning))
        return poses;
      for (int k = 0; k < std::min (directions, 6); ++k)
      {
        // A unit motion in the scaled coordinates moves the common part's rim by about its radius.
        const Eigen::Matrix<double, 6, 1> v = conditioning.eigenvectors.col (k);
        for (const double s : steps)
          for (const double sign : {1.0, -1.0})
            poses.push_back (motionAbout (conditioning.centroid, sign * s * v.head<3> (),
                                          sign * s * conditioning.radius * v.tail<3> ()) * pose);
      }
      return poses;
    }

    std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>>
    rivalPoses (const PoseConditioning& conditioning, const Eigen::Matrix4f& pose, int directions, const std::vector<double>& steps)
    {
      auto poses = motionPoses (conditioning, pose, directions, steps);
      if (!determinable (conditioning))
        return poses;
      for (int a = 0; a < 3; ++a)
        poses.push_back (motionAbout (conditioning.centroid, M_PI * conditioning.axes.col (a), Eigen::Vector3d::Zero ()) * pose);
      return poses;
    }

    std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>>
    screwTurnPoses (const PoseConditioning& conditioning, const Eigen::Matrix4f& pose, const std::vector<double>& turns)
    {
      std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>> poses;
      const Eigen::Matrix<double, 6, 1> screw = conditioning.eigenvectors.col (0);
      const double turn_rate = screw.head<3> ().norm ();
      if (!determinable (conditioning) || turn_rate < 0.25)
        return poses;
      for (const double angle : turns)
        for (const double sign : {1.0, -1.0})
        {
          if (sign < 0.0 && std::abs (angle - M_PI) < 1e-9)
            continue;
          // The motion scaled to turn by exactly the angle: the SE(3) exponential follows its screw.
          const double s = sign * angle / turn_rate;
          poses.push_back (motionAbout (conditioning.centroid, s * screw.head<3> (), s * conditioning.radius * screw.tail<3> ()) * pose);
        }
      return poses;
    }
  }
}
