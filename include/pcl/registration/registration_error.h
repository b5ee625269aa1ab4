/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Geometry>
#include <Eigen/StdVector>

#include <vector>

namespace pcl
{
  /** \brief The errors of an estimated rigid transformation against the ground truth (Section 7.1).
    * \ingroup registration
    */
  struct RegistrationError
  {
    /** \brief theta_e of Eq. 11, in degrees. */
    double rotation_deg = 0.0;
    /** \brief t_e of Eq. 12, in units of d_res. */
    double translation_resolutions = 0.0;
  };

  /** \brief Rotation error of Eqs. 10 and 11: the angle of R_d = R * R_gt^-1, in degrees.
    *
    * The acos argument (trace(R_d) - 1) / 2 is clamped to [-1, 1], since rounding pushes it just past 1
    * for (almost) equal rotations.
    * \param[in] rotation the estimated rotation R_i
    * \param[in] ground_truth the true rotation R_iGT
    * \return theta_e in [0, 180] degrees
    * \ingroup registration
    */
  double
  rotationErrorDeg (const Eigen::Matrix3d& rotation, const Eigen::Matrix3d& ground_truth);

  /** \brief Translation error of Eq. 12: ||t_i - t_iGT|| / d_res.
    * \param[in] translation the estimated translation t_i
    * \param[in] ground_truth the true translation t_iGT
    * \param[in] resolution d_res, the mesh resolution of the fine meshes (before reduction)
    * \return the error in units of d_res
    * \throw pcl::BadArgumentException when \a resolution is not positive and finite
    * \ingroup registration
    */
  double
  translationErrorResolutions (const Eigen::Vector3d& translation, const Eigen::Vector3d& ground_truth,
                               double resolution);

  /** \brief Both errors of Section 7.1 for an estimated rigid transformation.
    * \param[in] estimate the estimated transformation (R_i, t_i)
    * \param[in] ground_truth the true transformation (R_iGT, t_iGT)
    * \param[in] resolution d_res
    * \return theta_e (Eq. 11) and t_e (Eq. 12)
    * \throw pcl::BadArgumentException when \a resolution is not positive and finite
    * \ingroup registration
    */
  RegistrationError
  registrationError (const Eigen::Affine3d& estimate, const Eigen::Affine3d& ground_truth, double resolution);

  /** \brief Overlap of two views (Eq. 14): the fraction of the finite points of the view with fewer finite
    * points that have a point of the other view within \a max_distance, once both are mapped into the
    * common frame by their ground-truth poses. The paper counts corresponding vertices within 2 d_res.
    * \param[in] cloud_a, cloud_b the views, each in its own frame (NaN points are skipped)
    * \param[in] pose_a, pose_b their poses into the common frame
    * \param[in] max_distance the correspondence distance (2 d_res in the paper)
    * \return the overlap in [0, 1]
    * \throw pcl::BadArgumentException when \a max_distance is not positive
    * \throw InvalidScanException when a view has no finite point
    * \ingroup registration
    */
  double
  viewOverlap (const pcl::PointCloud<pcl::PointXYZ>& cloud_a, const Eigen::Affine3d& pose_a,
               const pcl::PointCloud<pcl::PointXYZ>& cloud_b, const Eigen::Affine3d& pose_b,
               double max_distance);

  /** \brief The motion G of the common frame that brings a set of estimated view poses closest to their
    * ground truth: the rigid G minimising sum_i sum_p || G E_i p - T_i p ||^2 over points p of each view
    * (Umeyama's closed form, without scale).
    *
    * Poses estimated for several views are defined only up to such a G, since their common frame is
    * arbitrary. Scoring them after fixing one view's pose to its ground truth charges every systematic
    * difference to the others: a turntable axis tilted by e against the ground truth's gives rotation
    * errors growing as 2 e sin(theta / 2), 2 e at the far side, where after G every view is about e off.
    * Trajectory benchmarks align the same way (the absolute trajectory error of Sturm et al., 2012).
    * \param[in] views each view's points in its own frame (NaN points are skipped); nullptr leaves a view out
    * \param[in] estimates E_i, each view's estimated pose into the estimated common frame
    * \param[in] truth T_i, each view's true pose
    * \param[in] samples_per_view points taken from each view, evenly over its finite points
    * \return G, to be applied as G * E_i
    * \throw pcl::BadArgumentException when the three lists differ in length, or fewer than 3 points are left
    * \ingroup registration
    */
  Eigen::Affine3d
  bestFitCommonFrame (const std::vector<const pcl::PointCloud<pcl::PointXYZ>*>& views,
                      const std::vector<Eigen::Affine3d, Eigen::aligned_allocator<Eigen::Affine3d>>& estimates,
                      const std::vector<Eigen::Affine3d, Eigen::aligned_allocator<Eigen::Affine3d>>& truth,
                      std::size_t samples_per_view = 2000);
}
