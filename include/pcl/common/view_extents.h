/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/object_dimensions.h>
#include <pcl/common/point_moments.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <vector>

namespace pcl
{
  /** \brief A view's points as the dimension checks see them (Eq. 1 and 9), measured once: their
    * number, centroid and scatter, and the bounding box of each run of consecutive points. Extents
    * along any axes then cost a few hundred box bounds and the points of the few boxes that can hold
    * the extreme, not a visit to every point: local verification checks D for every hypothesis that
    * reaches it, tens to hundreds per pair.
    * \ingroup common
    */
  class ViewExtents
  {
    public:
      ViewExtents () = default;

      /** \brief The finite points of \a cloud, in its order (a range image's rows keep runs compact). */
      template <typename PointT> explicit ViewExtents (const pcl::PointCloud<PointT>& cloud);

      /** \brief Number of finite points. */
      std::size_t size () const { return points_.size (); }
      /** \brief Their count, centroid and scatter. */
      const PointMoments& moments () const { return moments_; }

      /** \brief max over the points of \a direction . p, exactly (-infinity without points). */
      double support (const Eigen::Vector3d& direction) const;

    private:
      /** Runs of this many consecutive points share a box. */
      static constexpr std::size_t kRun = 64;

      /** Upper bound of \a direction . p over run \a r, from its box. */
      double bound (std::size_t r, const Eigen::Vector3d& direction) const;
      /** max of \a direction . p over run \a r's points. */
      double exact (std::size_t r, const Eigen::Vector3d& direction) const;

      std::vector<Eigen::Vector3d> points_;
      std::vector<Eigen::Vector3d> box_centres_, box_halves_;
      PointMoments moments_;
  };

  /** \brief registeredDimensionExcess() of two views, \a scene moved by \a t into \a model's frame,
    * from their ViewExtents: the union's principal frame from the two views' moments, each view's own
    * frame from its scatter, and the extents in them from the views' supports. Equal to it up to
    * rounding.
    * \throw InvalidScanException when the two views have fewer than three points
    */
  double
  registeredDimensionExcess (const ViewExtents& model, const ViewExtents& scene, const Eigen::Matrix4d& t,
                             const ObjectDimensions& dims, int checked = 3);
}
