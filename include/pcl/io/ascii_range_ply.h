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
    /** \brief Read an ASCII PLY range scan, such as the raw Stanford scans, in one pass over the text.
      *
      * pcl::PLYReader parses ASCII PLY through a callback per property and takes about 100 ms for a
      * 2 MB Stanford scan, as long as the whole registration of a pair should take; this reader gives
      * the same cloud several times faster. It reads the vertex element's x, y and z (skipping any
      * other property), skips elements it does not use (faces, for instance), and, when the file has
      * an `element range_grid` and `obj_info num_cols/num_rows` that agree with it, returns the
      * organized cloud of the grid with NaN in empty cells, as pcl::PLYReader does. is_dense is left
      * false when any point is not finite.
      *
      * \param[in] path the file
      * \param[out] cloud the points
      * \return false, with \a cloud untouched, when the file is not ASCII PLY or uses a layout this
      *         reader does not handle (binary, a grid without its size); read such files with pcl::PLYReader
      * \throw pcl::IOException when the file is ASCII PLY but malformed: truncated, a bad number, a
      *        grid cell naming a vertex that does not exist
      * \ingroup io
      */
    bool
    readAsciiRangePLY (const std::string& path, pcl::PointCloud<pcl::PointXYZ>& cloud);
  }
}
