/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace pcl
{
  /** \brief The noise of a range scan: a robust standard deviation of its points' distances from
    * the planes fitted to their neighbourhoods.
    *
    * Planes are fitted (least squares) to the neighbourhoods of \a samples points spread evenly over
    * the scan: the points within \a radius of the point across the normal of a first fit to the sphere
    * of that radius. Sigma is 1.4826 times the median distance of those neighbourhoods' points from
    * their planes (the median absolute deviation of a Gaussian). On a smooth surface
    * sampled densely the curvature adds about radius^2 / (2 R) per point, small next to d_res when
    * \a radius is a few d_res. Verification takes its tolerances from it: the noise belongs to the
    * scans, not to a hypothesis, so a wrong registration's poor fit cannot widen them.
    * \param[in] points the scan's points (NaN points are skipped)
    * \param[in] radius neighbourhood radius (> 0), e.g. 3 d_res
    * \param[in] samples neighbourhoods to fit (> 0)
    * \return sigma, in the points' units; 0 when no neighbourhood has 4 points
    * \throw pcl::BadArgumentException when \a radius or \a samples is not positive, or twice \a radius is
    *        not a finite float
    * \ingroup common
    */
  double
  estimateScanNoise (const pcl::PointCloud<pcl::PointNormal>& points, double radius, std::size_t samples = 500);
}
