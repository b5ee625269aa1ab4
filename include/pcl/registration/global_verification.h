/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/object_dimensions.h>
#include <pcl/common/point_moments.h>
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

        /** \brief Add every view of \a other, moved by \a pose (other's common frame -> this one): two
          * groups of registered views joined by one pairwise registration. Both must share D and d_res. */
        void merge (const GlobalVerification& other, const Eigen::Affine3d& pose);

        /** \brief max(D_L - D) in d_res, with the view under \a pose added to the registered ones.
          * \throw InvalidScanException when fewer than three finite points are given in all */
        double excess (const pcl::PointCloud<pcl::PointNormal>& cloud, const Eigen::Affine3d& pose) const;

        /** \brief max(D_L - D) in d_res, with every view of \a other, moved by \a pose, added.
          * \throw InvalidScanException when fewer than three finite points are given in all */
        double excess (const GlobalVerification& other, const Eigen::Affine3d& pose) const;

        /** \brief excess() <= tolerance. */
        bool accepts (const pcl::PointCloud<pcl::PointNormal>& cloud, const Eigen::Affine3d& pose) const
        {
          return excess (cloud, pose) <= params_.tolerance;
        }

        /** \brief Points kept of the registered views so far: the vertices of each view's convex hull. */
        std::size_t size () const { return points_.size (); }

        /** \brief Registered views so far. */
        std::size_t views () const { return frames_.size (); }

      private:
        /** One view's own principal axes and the extents of every registered point along them
          * (relative to anchor_), kept up to date as views are added, so that a check costs one pass
          * over the new points instead of one per view over all points. */
        struct Frame
        {
          bool valid = false;  ///< false: the view has fewer than three finite points, hence no axes
          Eigen::Matrix3d axes = Eigen::Matrix3d::Identity ();
          Eigen::Vector3d low = Eigen::Vector3d::Zero (), high = Eigen::Vector3d::Zero ();
        };

        /** A group holding one view, in the view's frame. */
        GlobalVerification
        single (const pcl::PointCloud<pcl::PointNormal>& cloud) const;

        /** Extents of this group's points and \a other's moved by \a pose, along \a axes (common frame). */
        Eigen::Vector3d
        unionExtents (const GlobalVerification& other, const Eigen::Affine3d& pose, const Eigen::Matrix3d& axes) const;

        /** \a frame of \a other moved by \a pose into this group, relative to anchor_. */
        Frame
        movedFrame (const Frame& frame, const GlobalVerification& other, const Eigen::Affine3d& pose) const;

        ObjectDimensions dims_;
        double resolution_;
        GlobalVerificationParams params_;
        /** The registered views' convex hull vertices (extents along any axes are taken at them), in the
          * common frame relative to anchor_. */
        std::vector<Eigen::Vector3f> points_;
        std::vector<Frame> frames_;
        PointMoments moments_;  ///< of every registered finite point, in the common frame
        /** The first finite point: points and extents are measured from it, which keeps the digits that
          * large coordinates would take. */
        Eigen::Vector3d anchor_ = Eigen::Vector3d::Zero ();
        bool anchored_ = false;
    };
  }
}
