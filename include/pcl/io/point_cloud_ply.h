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
    /** \brief Write a point cloud as binary little-endian PLY: every point (NaN ones too) as float x, y, z
      * and, for an organized cloud, the camera element pcl::PLYWriter writes with its viewport set to the
      * cloud's width and height, so that pcl::io::loadRangeScan() reads it back organized. The file is
      * written atomically (writeFileAtomically()).
      *
      * Unlike pcl::io::savePLYFileBinary it needs nothing from libpcl_io, whose VTK libraries would cost
      * every pcl_tensor_register process about 27 ms to load.
      * \throw pcl::IOException when the file cannot be written
      * \ingroup io
      */
    void
    savePointCloudPLY (const std::string& path, const pcl::PointCloud<pcl::PointXYZ>& cloud);
  }
}
