/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/range_scan_io.h>
#include <pcl/io/range_ply.h>
#include "file_input.h"
#include <pcl/common/tensor_exceptions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/common/point_tests.h>

#include <boost/algorithm/string/case_conv.hpp>

#include <fstream>
#include <new>
#include <stdexcept>
#include <cctype>
#include <cstdint>
#include <map>
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
      /** The unsigned numbers of one PCD header line; anything else is a broken header. */
      std::vector<unsigned long long>
      pcdNumbers (const std::vector<std::string>& values, const std::string& path, int line_no)
      {
        std::vector<unsigned long long> out;
        for (const auto& v : values)
        {
          std::size_t used = 0;
          unsigned long long n = 0;
          try
          {
            n = std::isdigit (static_cast<unsigned char> (v[0])) ? std::stoull (v, &used) : 0;
          }
          catch (const std::exception&)
          {
            used = 0;
          }
          if (used != v.size ())
            PCL_TENSOR_THROW (pcl::IOException, path << ":" << line_no << ": '" << v << "' is not a size or count");
          out.push_back (n);
        }
        return out;
      }

      using PcdNumbers = std::map<std::string, std::vector<unsigned long long>>;

      /** The first number of a header line, 0 when the line is missing. */
      long double
      firstNumber (PcdNumbers& n, const char* key)
      {
        return n[key].empty () ? 0.0L : static_cast<long double> (n[key][0]);
      }

      /** The bytes of one point: SIZE x COUNT over the fields, as PCL's point_step. */
      long double
      pointBytes (PcdNumbers& n)
      {
        long double bytes = 0.0L;
        for (std::size_t i = 0; i < n["SIZE"].size (); ++i)
          bytes += static_cast<long double> (n["SIZE"][i]) * (i < n["COUNT"].size () ? n["COUNT"][i] : 1ULL);
        return bytes;
      }

      /** PCL's PCD reader allocates points x point size from the header before reading any data, so a
        * garbage header asks for terabytes (found by fuzz_range_scan). No PCD, even compressed, holds
        * more than a thousand times its own size. */
      void
      requirePlausibleSize (PcdNumbers& n, const std::string& path)
      {
        const long double file_bytes = static_cast<long double> (std::ifstream (path, std::ios::binary | std::ios::ate).tellg ());
        const long double point_bytes = pointBytes (n);
        const long double points = std::max (firstNumber (n, "POINTS"), firstNumber (n, "WIDTH") * firstNumber (n, "HEIGHT"));
        const long double limit = std::max (64.0L * (1 << 20), 1024.0L * file_bytes);
        if (points * point_bytes > limit)
          PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' claims " << points << " points of " << point_bytes
                            << " bytes, far more than its " << file_bytes << " bytes can hold");
      }

      /** binary_compressed data starts with its compressed and uncompressed sizes. PCL's reader shrinks
        * its buffer to the uncompressed size it reads there, then unpacks WIDTH x HEIGHT points into it
        * all the same: a smaller size makes it write past the buffer (heap corruption, found by
        * fuzz_range_scan). \a in is at the start of the data. */
      void
      requireMatchingUncompressedSize (std::istream& in, PcdNumbers& n, const std::string& path)
      {
        std::uint32_t sizes[2] = {0, 0};  // compressed, uncompressed; in the machine's byte order, as PCL reads them
        if (!in.read (reinterpret_cast<char*> (sizes), sizeof (sizes)))
          PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' has binary_compressed data without its sizes");
        const long double expected = firstNumber (n, "WIDTH") * firstNumber (n, "HEIGHT") * pointBytes (n);
        if (static_cast<long double> (sizes[1]) != expected)
          PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' says its data uncompresses to " << sizes[1]
                            << " bytes; WIDTH x HEIGHT points take " << expected);
      }

      /** PCL 1.13's PCDReader segfaults on a file without a complete header (an empty file, text,
        * random bytes), so the header is checked here first: known keywords only, the mandatory
        * ones present, one SIZE, TYPE and COUNT entry per field, before a single DATA line, and a
        * size the file can hold. */
      void
      requirePcdHeader (const std::string& path)
      {
        static const std::set<std::string> known = {"VERSION", "FIELDS", "COLUMNS", "SIZE", "TYPE", "COUNT",
                                                     "WIDTH", "HEIGHT", "VIEWPOINT", "POINTS", "DATA"};
        static const std::set<std::string> mandatory = {"FIELDS", "SIZE", "TYPE", "WIDTH", "HEIGHT", "POINTS"};
        std::ifstream in (path, std::ios::binary);
        std::set<std::string> seen;
        PcdNumbers numbers;
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
          if (key == "SIZE" || key == "COUNT" || key == "WIDTH" || key == "HEIGHT" || key == "POINTS")
            numbers[key] = pcdNumbers (values, path, line_no);
          if (key == "DATA")
          {
            for (const auto& k : mandatory)
              if (!seen.count (k))
                PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' has no " << k << " line in its PCD header");
            requirePlausibleSize (numbers, path);
            if (values[0].rfind ("binary_compressed", 0) == 0)  // PCL too goes by the prefix
              requireMatchingUncompressedSize (in, numbers, path);
            return;
          }
        }
        PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' has no PCD header (up to a DATA line)");
      }

      /** What PCL's PCDReader.read (path, cloud) does, with the checks it lacks: PCL converts a file of
        * no points by binding a reference to element 0 of an empty vector, and trusts that the data holds width x height points with x, y and z. */
      void
      readPoints (pcl::PCDReader& reader, const std::string& path, pcl::PointCloud<pcl::PointXYZ>& cloud)
      {
        pcl::PCLPointCloud2 blob;
        int version = 0;
        int status = -1;
        try
        {
          status = reader.read (path, blob, cloud.sensor_origin_, cloud.sensor_orientation_, version);
        }
        catch (const std::length_error&)
        {
          // PCL's PCD reader sizes buffers from the header unchecked: a garbage SIZE asks for more
          // than a vector can hold (found by fuzz_range_scan).
          status = -1;
        }
        catch (const std::bad_alloc&)
        {
          status = -1;
        }
        if (status < 0)
          PCL_TENSOR_THROW (pcl::IOException, "cannot parse '" << path << "'");
        const std::size_t points = static_cast<std::size_t> (blob.width) * blob.height;
        if (points == 0)
          PCL_TENSOR_THROW (InvalidScanException, "'" << path << "' has no points");
        for (const char* axis : {"x", "y", "z"})
          if (pcl::getFieldIndex (blob, axis) < 0)
            PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' has no " << axis << " coordinate");
        if (blob.point_step == 0 || blob.row_step < static_cast<std::size_t> (blob.point_step) * blob.width ||
            blob.data.size () < static_cast<std::size_t> (blob.row_step) * blob.height)
          PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' holds fewer bytes than its " << points << " points need");
        pcl::fromPCLPointCloud2 (blob, cloud);
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
      if (ext == "ply")
      {
        // Not pcl::PLYReader: it is slower on ASCII and aborts on odd headers (see readRangePLY).
        readRangePLY (path, *scan.cloud);
      }
      else if (ext == "pcd")
      {
        requirePcdHeader (path);
        pcl::PCDReader reader;
        readPoints (reader, path, *scan.cloud);
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
