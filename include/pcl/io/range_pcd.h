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
    /** \brief Read a PCD range scan (DATA ascii, binary or binary_compressed) into a point cloud.
      *
      * The x, y and z fields are read (any PCD scalar type, converted to float) and every other field
      * is skipped; WIDTH x HEIGHT give the grid, and VIEWPOINT the cloud's sensor_origin_ and
      * sensor_orientation_, as pcl::PCDReader gives them. is_dense is false when any point is not
      * finite. The header must follow the PCD format: its entries in the order FIELDS, SIZE, TYPE,
      * COUNT (optional), WIDTH, HEIGHT, VIEWPOINT (optional), POINTS, DATA, each once.
      *
      * Why not pcl::PCDReader: PCL 1.13's reader trusts its header. Found by fuzz_range_scan and
      * valgrind: it segfaults on a file without a complete header, allocates what a garbage SIZE or
      * POINTS line asks (terabytes), writes past its buffer in its ASCII reader and when binary_compressed
      * data uncompress to fewer bytes than the points need. This reader throws instead.
      *
      * \param[in] path the file
      * \param[out] cloud the points; untouched when an exception is thrown
      * \throw pcl::IOException when the file cannot be read, is not PCD, or is malformed: a header out
      *        of order or inconsistent, no x, y and z, a bad number, data cut short or not
      *        uncompressing to WIDTH x HEIGHT points
      * \ingroup io
      */
    void
    readRangePCD (const std::string& path, pcl::PointCloud<pcl::PointXYZ>& cloud);
  }
}
