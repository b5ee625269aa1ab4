/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_viewpoint.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <random>

namespace pcl
{
  /** \brief Add zero-mean Gaussian noise to every finite point along its line of sight, the scanner's
    * viewing direction (Section 7.5, where sigma = 1..4 d_res).
    *
    * The noise moves a point along the ray from the sensor through it, so a noisy range image keeps its
    * grid: perspective points move along (p - sensor origin), orthographic ones along the sensor axis.
    * NaN cells stay NaN.
    * \param[in,out] cloud the range image, in the same frame as \a viewpoint
    * \param[in] viewpoint the sensor (e.g. RenderedView::viewpoint for a rendered view)
    * \param[in] sigma standard deviation in metres (multiply a sigma in d_res units by d_res)
    * \param[in,out] rng the random engine; seed it explicitly for repeatable noise
    * \throw pcl::BadArgumentException when sigma is negative or not finite
    * \ingroup simulation
    */
  void
  addViewingDirectionNoise (pcl::PointCloud<pcl::PointXYZ>& cloud, const ScanViewpoint& viewpoint,
                            double sigma, std::mt19937& rng);
}
