/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Core>

#include <vector>

namespace pcl
{
  /** \brief The object's approximate bounding dimensions D and the parameters derived from it.
    *
    * D is the elementwise maximum, over all views, of each view's extents after alignment with its
    * principal axes (Eq. 1). The vertex-pair distance limits follow Eq. 2 and the bin size Eq. 3.
    * \ingroup common
    */
  struct ObjectDimensions
  {
    /** \brief D = [D_x D_y D_z] (Eq. 1), sorted from the largest principal extent to the smallest. */
    Eigen::Vector3d D = Eigen::Vector3d::Zero ();

    /** \brief Whether D is set: every dimension positive. */
    bool isSet () const { return (D.array () > 0.0).all (); }
    /** \brief mean(D_x, D_y, D_z). */
    double mean () const { return D.mean (); }
    /** \brief d_min = mean(D)/6 (Eq. 2). */
    double dMin () const { return mean () / 6.0; }
    /** \brief d_max = mean(D)/4 (Eq. 2). */
    double dMax () const { return mean () / 4.0; }
    /** \brief Bin size b_s = mean(D)/30 (Eq. 3). */
    double binSize () const { return mean () / 30.0; }
    /** \brief Local-verification tolerance t_D = mean(D)/10 (Section 4.1). */
    double verificationTolerance () const { return mean () / 10.0; }
  };

  /** \brief Extents of a point set after aligning it with its principal axes (Eq. 1 for one view, Eq. 9
    * for registered views), sorted from largest to smallest, computed in double precision.
    * Non-finite points are skipped.
    * \throw InvalidScanException when fewer than three finite points remain.
    */
  Eigen::Vector3d
  principalExtents (const std::vector<Eigen::Vector3d>& points);

  /** \brief principalExtents() of a cloud's finite points. */
  template <typename PointT> Eigen::Vector3d
  principalExtents (const pcl::PointCloud<PointT>& cloud);

  /** \brief Extents of several point sets taken together (Eq. 9 over M'_ms, or over L views in
    * Section 4.2), in one common frame.
    */
  template <typename PointT> Eigen::Vector3d
  principalExtents (const std::vector<const pcl::PointCloud<PointT>*>& clouds);

  /** \brief How far extents exceed D: max over the \a checked largest extents of (extents - D), as
    * Eq. 9 is compared with D in Sections 4.1 and 4.2.
    * \param[in] extents principal extents, sorted from largest to smallest (principalExtents())
    * \param[in] dims the object's D
    * \param[in] checked how many of the largest extents are compared (clamped to 1..3)
    */
  double
  dimensionExcess (const Eigen::Vector3d& extents, const ObjectDimensions& dims, int checked = 3);

  /** \brief How far registered views stick out of D (Sections 4.1 and 4.2): the smallest
    * dimensionExcess() of their combined points over the principal frame of the combination (Eq. 9)
    * and the principal frame of each view alone, the frames in which Eq. 1 measured D.
    *
    * Two views' combined principal axes turn with what they cover, so correct views can exceed D in
    * them though they fit inside the object. The views' own frames are fixed by the views, not chosen
    * to fit: a search over all frames for the best fit let wrong poses through
    * (doc/design.md#dimension-checks-on-two-extents).
    * \param[in] points the registered views' points, view after view, in one frame
    * \param[in] view_starts the index in \a points of each view's first point, ascending
    * \param[in] dims the object's D
    * \param[in] checked how many of the largest extents are compared (clamped to 1..3)
    * \throw InvalidScanException when \a points has fewer than three finite points
    * \throw BadArgumentException when \a view_starts is not ascending within \a points
    */
  double
  registeredDimensionExcess (const std::vector<Eigen::Vector3d>& points, const std::vector<std::size_t>& view_starts,
                             const ObjectDimensions& dims, int checked = 3);

  /** \brief D from all the views of an object (Eq. 1). */
  template <typename PointT> ObjectDimensions
  computeObjectDimensions (const std::vector<const pcl::PointCloud<PointT>*>& views);

  /** \brief D from each view's principalExtents() (Eq. 1: their elementwise maximum), for views whose
    * extents are known without their points (a cache).
    * \throw InvalidScanException when \a extents is empty
    */
  ObjectDimensions
  objectDimensionsFromExtents (const std::vector<Eigen::Vector3d>& extents);

  /** \brief D as a user gives it, in any order, sorted from largest to smallest as Eq. 1 gives it, so
    * that tensors computed for a given D are found again whatever order it was written in. Not set
    * (ObjectDimensions::isSet() false) when any dimension is not positive: D is then measured.
    */
  ObjectDimensions
  givenObjectDimensions (const Eigen::Vector3d& D);
}
