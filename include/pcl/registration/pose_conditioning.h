/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/search/bounded_nearest_search.h>

#include <Eigen/Core>
#include <Eigen/StdVector>

#include <cstddef>
#include <vector>

namespace pcl
{
  namespace registration
  {
    /** \brief How well the surface two registered views share pins their relative pose down: the
      * spectrum of the 6x6 point-to-plane information matrix of their close pairs.
      * \ingroup registration
      */
    struct PoseConditioning
    {
      std::size_t pairs = 0;   ///< source points with a target point (and its normal) within the distance
      double radius = 0.0;     ///< RMS distance of the paired source points from their centroid
      /** Eigenvalues of the information matrix, ascending, per pair; rotations are taken about the pairs'
        * centroid and scaled by \a radius, so they weigh as translations of the patch's rim do. */
      Eigen::Matrix<double, 6, 1> eigenvalues = Eigen::Matrix<double, 6, 1>::Zero ();
      /** Smallest eigenvalue over the largest: 0 when some motion (sliding along a plane or a
        * cylinder, turning about an axis of revolution) leaves every pair on its tangent plane; 0 with
        * fewer than 6 pairs. */
      double ratio = 0.0;
      /** The motions of the eigenvalues, column k for eigenvalue k: (scaled rotation, translation). */
      Eigen::Matrix<double, 6, 6> eigenvectors = Eigen::Matrix<double, 6, 6>::Identity ();
      /** Centroid of the paired source points, moved by the pose (the target's frame). */
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero ();
      /** Principal axes of the paired source points, as columns, by ascending spread. */
      Eigen::Matrix3d axes = Eigen::Matrix3d::Identity ();
    };

    /** \brief \a pose moved along each of the \a directions least constrained motions of \a
      * conditioning by each of \a steps and their negatives: a step of s turns the common part by s
      * |omega| radians and moves it by s |v| times its radius, for the motion's unit (omega, v). Each is
      * applied about the common part's centroid, in the target's frame. None when \a conditioning has
      * too few pairs.
      * \ingroup registration
      */
    std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>>
    motionPoses (const PoseConditioning& conditioning, const Eigen::Matrix4f& pose, int directions,
                 const std::vector<double>& steps);

    /** \brief Poses a rival registration could take near \a pose, for checking that \a pose is the
      * only one the views verify: motionPoses(), and \a pose turned half-way about each principal
      * axis of the common part (a twofold symmetry). None when \a conditioning has too few pairs.
      * \ingroup registration
      */
    std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>>
    rivalPoses (const PoseConditioning& conditioning, const Eigen::Matrix4f& pose, int directions,
                const std::vector<double>& steps);

    /** \brief \a pose turned along the screw of the least constrained motion of \a conditioning by
      * each of \a turns (radians) and its negative (a half turn once): the turns a surface of
      * revolution allows, however far, which steps along a motion that also translates do not reach.
      * None when that motion hardly turns (|omega| < 0.25: its screw axis would lie over 4 radii
      * away) or \a conditioning has too few pairs.
      * \ingroup registration
      */
    std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>>
    screwTurnPoses (const PoseConditioning& conditioning, const Eigen::Matrix4f& pose, const std::vector<double>& turns);

    /** \brief The conditioning of the pose \a t of \a source on \a target: each source point moved by
      * \a t and paired with its nearest target point within \a max_distance contributes the row
      * [((s - c) x n) / r, n] (n: the target point's normal, c and r: the pairs' centroid and RMS
      * radius) to J, and the result is the spectrum of J^T J / pairs. A pose is determined by the
      * pairs only in as many directions as the matrix has eigenvalues well above zero; a registration
      * that rests on a surface of revolution, a plane or a cylinder is not.
      * \param[in] source points to move (e.g. the scene)
      * \param[in] target points with normals (the model), searched through \a search
      * \param[in] search the nearest-neighbour search built on \a target
      * \param[in] t the pose of the source
      * \param[in] max_distance pairs farther apart are left out (e.g. 2 d_res)
      * \ingroup registration
      */
    PoseConditioning
    computePoseConditioning (const pcl::PointCloud<pcl::PointNormal>& source, const pcl::PointCloud<pcl::PointNormal>& target,
                             const pcl::BoundedNearestSearch& search, const Eigen::Matrix4f& t, double max_distance);
  }
}
