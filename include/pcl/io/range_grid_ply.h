/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>

namespace pcl
{
  namespace io
  {
    /** \brief Write an organized range image as an ASCII PLY file with an `element range_grid`, like the
      * raw Stanford scans: only the finite points are written as vertices, and the grid lists, row by
      * row, the vertex of each cell (or none for a NaN cell). pcl::io::loadRangeScan() reads it back as
      * an organized cloud with the same NaN pattern and, thanks to 9 significant digits, the same floats.
      *
      * pcl::PLYWriter can write a range_grid too (use_camera = false), but it prints floats with 6
      * significant digits whatever precision it is given, so its round trip is not exact.
      * \throw pcl::BadArgumentException when the cloud is not organized (height < 2) or has fewer than one
      * finite point
      * \throw pcl::IOException when the file cannot be written
      * \ingroup io
      */
    void
    saveRangeGridPLY (const std::string& path, const pcl::PointCloud<pcl::PointXYZ>& cloud);
  }
}
