/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/range_scan_io.h>
#include <pcl/common/grid_sensor_fit.h>
#include <pcl/io/range_pcd.h>
#include <pcl/io/range_ply.h>
#include "file_input.h"
#include <pcl/common/tensor_exceptions.h>
#include <pcl/common/point_tests.h>

#include <boost/algorithm/string/case_conv.hpp>

namespace pcl
{
  namespace io
  {
    namespace
    {
      std::string
      extensionOf (const std::string& path)
      {
        const auto dot = path.find_last_of ('.');
        return dot == std::string::npos ? std::string () : boost::algorithm::to_lower_copy (path.substr (dot + 1));
      }

      /** Drop non-finite points of an unorganized cloud; organized clouds keep their grid. */
      void
      dropNonFiniteIfUnorganized (pcl::PointCloud<pcl::PointXYZ>& cloud)
      {
        if (cloud.isOrganized ())
          return;
        pcl::PointCloud<pcl::PointXYZ> finite;
        finite.reserve (cloud.size ());
        for (const auto& p : cloud)
          if (pcl::isXYZFinite (p))
            finite.push_back (p);
        finite.header = cloud.header;
        finite.sensor_origin_ = cloud.sensor_origin_;
        finite.sensor_orientation_ = cloud.sensor_orientation_;
        cloud.swap (finite);
      }
    }

    std::size_t
    updateDenseFlag (pcl::PointCloud<pcl::PointXYZ>& cloud)
    {
      std::size_t finite = 0;
      for (const auto& p : cloud)
        finite += pcl::isXYZFinite (p) ? 1 : 0;
      cloud.is_dense = (finite == cloud.size ());
      return finite;
    }

    RangeScan
    loadRangeScan (const std::string& path)
    {
      detail::requireReadableFile (path);
      RangeScan scan;
      const std::string ext = extensionOf (path);
      if (ext == "ply")  // not pcl::PLYReader: slower on ASCII, and it aborts on odd headers (see readRangePLY)
      {
        readRangePLY (path, *scan.cloud);
        // A PLY carries no sensor pose, but a scanner's grid shows where its lines of sight ran.
        const GridSensorFit fit = fitPushbroomSensor (*scan.cloud);
        if (fit.found)
          scan.viewpoint = fit.viewpoint;
      }
      else if (ext == "pcd")
      {
        // Not pcl::PCDReader: it trusts its header (see readRangePCD).
        readRangePCD (path, *scan.cloud);
        scan.viewpoint = ScanViewpoint::fromCloud (*scan.cloud);
      }
      else
        PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' is neither .ply nor .pcd");

      dropNonFiniteIfUnorganized (*scan.cloud);
      scan.finite_points = updateDenseFlag (*scan.cloud);
      if (scan.finite_points < 3)
        PCL_TENSOR_THROW (InvalidScanException, "'" << path << "' has " << scan.finite_points
                          << " finite points; a range scan needs at least 3");
      return scan;
    }
  }
}
