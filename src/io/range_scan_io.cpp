/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/range_scan_io.h>
#include "file_input.h"
#include <pcl/common/tensor_exceptions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/common/point_tests.h>

#include <boost/algorithm/string/case_conv.hpp>

#include <fstream>
#include <set>
#include <sstream>
#include <vector>


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

    namespace
    {
      /** PCL 1.13's PCDReader segfaults on a file without a complete header (an empty file, text,
        * random bytes), so the header is checked here first: known keywords only, the mandatory
        * ones present, one SIZE, TYPE and COUNT entry per field, before a single DATA line. */
      void
      requirePcdHeader (const std::string& path)
      {
        static const std::set<std::string> known = {"VERSION", "FIELDS", "COLUMNS", "SIZE", "TYPE", "COUNT",
                                                     "WIDTH", "HEIGHT", "VIEWPOINT", "POINTS", "DATA"};
        static const std::set<std::string> mandatory = {"FIELDS", "SIZE", "TYPE", "WIDTH", "HEIGHT", "POINTS"};
        std::ifstream in (path, std::ios::binary);
        std::set<std::string> seen;
        std::size_t fields = 0;
        std::string line;
        for (int line_no = 1; line_no <= 64 && std::getline (in, line); ++line_no)
        {
          std::istringstream words (line);
          std::string key;
          if (!(words >> key) || key[0] == '#')
            continue;
          std::vector<std::string> values;
          for (std::string v; words >> v;)
            values.push_back (v);
          if (!known.count (key) || values.empty ())
            break;
          if (key == "FIELDS" || key == "COLUMNS")
            fields = values.size ();
          else if ((key == "SIZE" || key == "TYPE" || key == "COUNT") && values.size () != fields)
            PCL_TENSOR_THROW (pcl::IOException, path << ":" << line_no << ": " << key << " has " << values.size ()
                              << " entries for " << fields << " fields");
          seen.insert (key == "COLUMNS" ? "FIELDS" : key);
          if (key == "DATA")
          {
            for (const auto& k : mandatory)
              if (!seen.count (k))
                PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' has no " << k << " line in its PCD header");
            return;
          }
        }
        PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' has no PCD header (up to a DATA line)");
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
      const detail::QuietPclConsole quiet;
      const std::string ext = extensionOf (path);
      int status = -1;
      if (ext == "ply")
      {
        pcl::PLYReader reader;
        status = reader.read (path, *scan.cloud);
      }
      else if (ext == "pcd")
      {
        requirePcdHeader (path);
        pcl::PCDReader reader;
        status = reader.read (path, *scan.cloud);
        if (status >= 0)
          scan.viewpoint = ScanViewpoint::fromCloud (*scan.cloud);
      }
      else
        PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' is neither .ply nor .pcd");
      if (status < 0)
        PCL_TENSOR_THROW (pcl::IOException, "cannot parse '" << path << "' as " << ext);

      dropNonFiniteIfUnorganized (*scan.cloud);
      scan.finite_points = updateDenseFlag (*scan.cloud);
      if (scan.finite_points < 3)
        PCL_TENSOR_THROW (InvalidScanException, "'" << path << "' has " << scan.finite_points
                          << " finite points; a range scan needs at least 3");
      return scan;
    }
  }
}
