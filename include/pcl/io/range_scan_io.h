/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_viewpoint.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>

namespace pcl
{
  namespace io
  {
    /** \brief One range scan as read from a file. */
    struct RangeScan
    {
      /** \brief The points. Organized (width x height, NaN in empty cells) when the file has a grid,
        * such as the raw Stanford PLY scans' range_grid; otherwise unorganized and NaN-free.
        * is_dense is set from the data, never trusted from the reader.
        */
      pcl::PointCloud<pcl::PointXYZ>::Ptr cloud{new pcl::PointCloud<pcl::PointXYZ>};
      /** \brief The sensor: from the file's sensor origin/orientation (PCD); for a PLY grid that a
        * pushbroom explains (the raw Stanford scans; fitPushbroomSensor), that pushbroom; else +z
        * orthographic. */
      ScanViewpoint viewpoint = ScanViewpoint::fromPositiveZ ();
      /** \brief Number of finite points. */
      std::size_t finite_points = 0;
    };

    /** \brief Read a range scan from a PLY (ASCII or binary, with or without range_grid) or PCD file.
      * It reads through readRangePLY() and readRangePCD(), not PCL's readers, which abort or write past
      * their buffers on malformed files.
      * \param[in] path the file to read
      * \return the scan
      * \throw pcl::IOException when the file is missing, unreadable, of an unknown format or malformed
      * \throw pcl::InvalidScanException when it holds fewer than three finite points
      */
    RangeScan
    loadRangeScan (const std::string& path);

    /** \brief Set is_dense from the data: true only when every point is finite. PCL's PLY reader marks
      * organized Stanford scans dense although their empty cells are NaN.
      * \return the number of finite points
      */
    std::size_t
    updateDenseFlag (pcl::PointCloud<pcl::PointXYZ>& cloud);
  }
}
