/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/object_dimensions.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Geometry>

#include <vector>

namespace pcl
{
  namespace registration
  {
    /** \brief Settings of GlobalVerification. */
    struct GlobalVerificationParams
    {
      /** How far the combined dimensions of all registered views may exceed D, in d_res (Section 4.2: 4). */
      double tolerance = 4.0;
      /** How many of the largest principal extents are compared with D: 2, as in local verification
        * (TensorVerificationParams::checked_dimensions), since Eq. 1 underestimates the thinnest.
        * \note The paper compares all 3; see doc/design.md#dimension-checks-on-two-extents. */
      int checked_dimensions = 2;
    };

    /** \brief Global verification (Section 4.2; Fig. 7, steps 15 and 16): each time a view is added
      * to the registered views, the combined bounding dimensions D_L of all of them (Eq. 9, along
      * their principal axes, or along any one view's own: registeredDimensionExcess) may exceed the
      * object's D by at most 4 d_res. A pairwise registration that passed local verification can
      * still be wrong for the object as a whole (a symmetric or flat object matched the wrong way
      * round); this catches it.
      * \ingroup registration
      */
    class GlobalVerification
    {
      public:
        /** \param[in] dims D of the object (Eq. 1, from all its views)
          * \param[in] resolution d_res, the unit of the tolerance
          * \param[in] params tolerance and checked extents
          * \throw pcl::BadArgumentException on a non-positive resolution or a negative tolerance */
        GlobalVerification (const ObjectDimensions& dims, double resolution, const GlobalVerificationParams& params = {});

        /** \brief Add a registered view: its points under \a pose (view -> common frame). */
        void addView (const pcl::PointCloud<pcl::PointNormal>& cloud, const Eigen::Affine3d& pose);

        /** \brief max(D_L - D) in d_res, with the view under \a pose added to the registered ones.
          * \throw InvalidScanException when fewer than three finite points are given in all */
        double excess (const pcl::PointCloud<pcl::PointNormal>& cloud, const Eigen::Affine3d& pose) const;

        /** \brief excess() <= tolerance. */
        bool accepts (const pcl::PointCloud<pcl::PointNormal>& cloud, const Eigen::Affine3d& pose) const
        {
          return excess (cloud, pose) <= params_.tolerance;
        }

        /** \brief Points of the registered views so far, in the common frame. */
        std::size_t size () const { return points_.size (); }

      private:
        ObjectDimensions dims_;
        double resolution_;
        GlobalVerificationParams params_;
        std::vector<Eigen::Vector3d> points_;
        /** Where each registered view's points start in points_. */
        std::vector<std::size_t> view_starts_;
    };
  }
}
