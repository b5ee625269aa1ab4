/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace pcl
{
  /** \brief Count, centroid and scatter of a set of points: the principal axes of a union of sets
    * (the frame of Eq. 1 and 9) follow from theirs, without another pass over the points.
    * \ingroup common
    */
  struct PointMoments
  {
    double count = 0.0;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero ();
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero ();  ///< the sum of (p - mean)(p - mean)^T
  };

  /** \brief The moments of \a points, in two passes: the centroid first, so that the scatter does not
    * lose digits to large coordinates.
    * \ingroup common
    */
  PointMoments
  computePointMoments (const std::vector<Eigen::Vector3d>& points);

  /** \brief The moments of the union of \a a and \a b moved by \a pose, in \a a's frame (Chan, Golub
    * and LeVeque's pairwise update).
    * \ingroup common
    */
  PointMoments
  unitePointMoments (const PointMoments& a, const PointMoments& b, const Eigen::Affine3d& pose);
}
