/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_viewpoint.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <vector>

namespace pcl
{
  /** \brief Which pixels of an organized range image are specks: small groups of returns that stand
    * in front of the surface around them (dust, inter-reflections), with a depth jump on every side.
    *
    * Pixels are grouped over the 8-neighbourhood, two neighbours joining when they lie within
    * \a jump grid spacings of each other (the spacing is the median distance between finite
    * 4-neighbours). A group of at most \a max_pixels pixels is a speck when surface surrounds it:
    * every neighbour outside it is a return that lies behind it, farther from the sensor along the
    * line of sight than across it. A grazing surface has neighbours both nearer and farther, and a
    * part of the object cut off by dropout or a hole borders empty pixels; neither is a speck.
    *
    * Why it matters: the dimension checks of Eq. 9 take extents, and a speck tens of d_res in front
    * of the surface sets them alone (doc/design.md#speck-removal).
    * \param[in] cloud an organized range image (an unorganized cloud has no speck: no pixel has sides)
    * \param[in] viewpoint the sensor, for the lines of sight
    * \param[in] max_pixels the largest speck, in pixels (0: none is a speck)
    * \param[in] jump the least depth jump around a speck, in grid spacings (> 0)
    * \return one flag per point, true for a speck's pixel
    * \throw pcl::BadArgumentException on a negative \a max_pixels or a non-positive \a jump
    * \ingroup surface
    */
  std::vector<bool>
  speckPixels (const pcl::PointCloud<pcl::PointXYZ>& cloud, const ScanViewpoint& viewpoint, int max_pixels, double jump);

  /** \brief Set the speck pixels (speckPixels()) of an organized range image to NaN, keeping its grid,
    * and mark it not dense when any was set.
    * \return the number of pixels emptied
    */
  std::size_t
  removeSpecks (pcl::PointCloud<pcl::PointXYZ>& cloud, const ScanViewpoint& viewpoint, int max_pixels, double jump);

  /** \brief Set the pixels flagged in \a speck (one flag per point, as speckPixels() returns them) to
    * NaN, and mark \a cloud not dense when any was set.
    * \return the number of pixels emptied
    */
  std::size_t
  removeSpecks (pcl::PointCloud<pcl::PointXYZ>& cloud, const std::vector<bool>& speck);

  /** \brief Check speckPixels()'s parameters without an image.
    * \throw pcl::BadArgumentException on a negative \a max_pixels or a non-positive or infinite \a jump
    */
  void
  checkSpeckParameters (int max_pixels, double jump);
}
