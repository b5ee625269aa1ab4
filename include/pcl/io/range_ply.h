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
    /** \brief Read a PLY range scan (ASCII, binary_little_endian or binary_big_endian), such as the
      * raw Stanford scans, into a point cloud.
      *
      * The vertex element's x, y and z are read (any PLY scalar type, converted to float) and every
      * other property and element is skipped. The cloud is organized when the file says how, as
      * pcl::PLYReader would read it: an `element range_grid` whose cell count is `obj_info num_cols`
      * x `num_rows` (the Stanford scans; empty cells become NaN), or a `camera` element whose
      * viewportx x viewporty equals the vertex count (organized clouds written by pcl::PLYWriter).
      * Otherwise the cloud is unorganized. is_dense is false when any point is not finite.
      *
      * Why not pcl::PLYReader: it parses ASCII through a callback per value (several times slower on a
      * Stanford scan; doc/design.md#own-ply-and-pcd-readers), and PCL 1.13's reader asserts, aborting the
      * process, on headers that are merely odd (an obj_info line with leading blanks, a list property
      * in the vertex element, more vertices than grid cells), all found by fuzz_range_scan. This reader
      * throws instead.
      *
      * \param[in] path the file
      * \param[out] cloud the points; untouched when an exception is thrown
      * \throw pcl::IOException when the file cannot be read, is not PLY, or is malformed: an unknown
      *        format or type, no x, y and z, truncated data, a bad number, more instances than the file
      *        can hold, a grid cell naming a vertex that does not exist
      * \ingroup io
      */
    void
    readRangePLY (const std::string& path, pcl::PointCloud<pcl::PointXYZ>& cloud);
  }
}
