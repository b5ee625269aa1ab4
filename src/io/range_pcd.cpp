/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/range_pcd.h>
#include "ascii_number.h"
#include "file_input.h"
#include "lzf_decompress.h"
#include <pcl/io/range_scan_io.h>  // updateDenseFlag
#include <pcl/common/tensor_exceptions.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string_view>
#include <vector>

namespace pcl
{
  namespace io
  {
    namespace
    {
      struct PcdField
      {
        std::string name;
        std::size_t size = 4;    ///< bytes of one value
        char type = 'F';         ///< F (floating point), I (signed) or U (unsigned)
        std::size_t count = 1;   ///< values per point
        std::size_t offset = 0;  ///< in a point of the binary layout
      };

      enum class PcdData { Ascii, Binary, BinaryCompressed };

      struct PcdHeader
      {
        std::vector<PcdField> fields;
        unsigned long long width = 0, height = 0, points = 0;
        Eigen::Vector4f origin = Eigen::Vector4f::Zero ();
        Eigen::Quaternionf orientation = Eigen::Quaternionf::Identity ();
        PcdData data = PcdData::Ascii;
        std::size_t point_step = 0;
      };

      unsigned long long
      parseCount (const std::string& v, const std::string& path, int line_no)
      {
        unsigned long long n = 0;
        const auto result = std::from_chars (v.data (), v.data () + v.size (), n);
        if (result.ec != std::errc () || result.ptr != v.data () + v.size ())
          detail::throwAtLine (path, line_no, "'" + v + "' is not a size or count");
        return n;
      }

      /** The header entries in the order the PCD format prescribes; VERSION, COUNT and VIEWPOINT may
        * be left out. */
      const std::vector<std::string> kEntries = {"VERSION", "FIELDS", "SIZE", "TYPE", "COUNT",
                                                 "WIDTH", "HEIGHT", "VIEWPOINT", "POINTS", "DATA"};

      void
      parseEntry (const std::string& key, const std::vector<std::string>& values, PcdHeader& h,
                  const std::string& path, int line_no)
      {
        if (key == "FIELDS")
        {
          h.fields.resize (values.size ());
          for (std::size_t i = 0; i < values.size (); ++i)
            h.fields[i].name = values[i];
          return;
        }
        if ((key == "SIZE" || key == "TYPE" || key == "COUNT") && values.size () != h.fields.size ())
          detail::throwAtLine (path, line_no, key + " has " + std::to_string (values.size ()) + " entries for "
                       + std::to_string (h.fields.size ()) + " fields");
        for (std::size_t i = 0; key == "SIZE" && i < values.size (); ++i)
          h.fields[i].size = parseCount (values[i], path, line_no);
        for (std::size_t i = 0; key == "TYPE" && i < values.size (); ++i)
          h.fields[i].type = (values[i].size () == 1) ? values[i][0] : '?';
        for (std::size_t i = 0; key == "COUNT" && i < values.size (); ++i)
          h.fields[i].count = parseCount (values[i], path, line_no);
        if (key == "WIDTH")
          h.width = parseCount (values[0], path, line_no);
        else if (key == "HEIGHT")
          h.height = parseCount (values[0], path, line_no);
        else if (key == "POINTS")
          h.points = parseCount (values[0], path, line_no);
        else if (key == "VIEWPOINT")
        {
          float v[7];
          if (values.size () != 7)
            detail::throwAtLine (path, line_no, "VIEWPOINT needs 7 numbers");
          for (int k = 0; k < 7; ++k)
            if (!detail::parseFloat (values[k].data (), values[k].data () + values[k].size (), v[k]))
              detail::throwAtLine (path, line_no, "'" + values[k] + "' is not a number");
          h.origin = Eigen::Vector4f (v[0], v[1], v[2], 0.0f);
          h.orientation = Eigen::Quaternionf (v[3], v[4], v[5], v[6]);
        }
        else if (key == "DATA")
        {
          if (values[0] == "ascii")
            h.data = PcdData::Ascii;
          else if (values[0] == "binary")
            h.data = PcdData::Binary;
          else if (values[0] == "binary_compressed")
            h.data = PcdData::BinaryCompressed;
          else
            detail::throwAtLine (path, line_no, "unknown DATA '" + values[0] + "'");
        }
      }

      bool
      isValidType (const PcdField& f)
      {
        if (f.type == 'F')
          return f.size == 4 || f.size == 8;
        return (f.type == 'I' || f.type == 'U') && (f.size == 1 || f.size == 2 || f.size == 4 || f.size == 8);
      }

      /** What the entries must say together: known types, x, y and z, and WIDTH x HEIGHT = POINTS. */
      void
      requireConsistent (PcdHeader& h, const std::vector<bool>& seen, const std::string& path)
      {
        for (const char* needed : {"FIELDS", "SIZE", "TYPE", "WIDTH", "HEIGHT", "POINTS"})
          if (!seen[std::find (kEntries.begin (), kEntries.end (), needed) - kEntries.begin ()])
            PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' has no " << needed << " line in its PCD header");
        for (auto& f : h.fields)
        {
          if (!isValidType (f) || f.count == 0 || f.count > 1000000)
            PCL_TENSOR_THROW (pcl::IOException, "'" << path << "': field '" << f.name << "' has SIZE " << f.size
                              << ", TYPE " << f.type << " and COUNT " << f.count);
          f.offset = h.point_step;
          h.point_step += f.size * f.count;
        }
        for (const char* axis : {"x", "y", "z"})
          if (std::none_of (h.fields.begin (), h.fields.end (), [&] (const PcdField& f) { return f.name == axis && f.count == 1; }))
            PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' has no " << axis << " coordinate");
        if (static_cast<long double> (h.width) * h.height != static_cast<long double> (h.points))
          PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' has WIDTH " << h.width << " x HEIGHT " << h.height
                            << " != POINTS " << h.points);
      }

      /** The header's lines up to DATA, read from \a in, which is left at the data. */
      PcdHeader
      parseHeader (std::istream& in, const std::string& path)
      {
        PcdHeader h;
        int last_entry = -1;
        std::vector<bool> seen (kEntries.size (), false);
        std::string line;
        for (int line_no = 1; std::getline (in, line); ++line_no)
        {
          std::istringstream words (line);
          std::string key;
          if (!(words >> key) || key[0] == '#')
            continue;
          if (key == "COLUMNS")  // the old name
            key = "FIELDS";
          const auto entry = std::find (kEntries.begin (), kEntries.end (), key);
          if (entry == kEntries.end ())
            detail::throwAtLine (path, line_no, "'" + key + "' is not a PCD header entry");
          const int rank = static_cast<int> (entry - kEntries.begin ());
          if (rank <= last_entry)
            detail::throwAtLine (path, line_no, key + " is repeated or out of order");
          last_entry = rank;
          seen[rank] = true;
          std::vector<std::string> values;
          for (std::string v; words >> v;)
            values.push_back (v);
          if (values.empty ())
            detail::throwAtLine (path, line_no, key + " without a value");
          parseEntry (key, values, h, path, line_no);
          if (key == "DATA")
          {
            requireConsistent (h, seen, path);
            return h;
          }
        }
        PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' has no PCD header (up to a DATA line)");
      }

      /** One value of field \a f at \a p, whatever its type. */
      double
      valueAt (const char* p, const PcdField& f)
      {
        const auto as = [p] (auto value) { std::memcpy (&value, p, sizeof (value)); return static_cast<double> (value); };
        switch (f.type)
        {
          case 'F': return f.size == 4 ? as (float ()) : as (double ());
          case 'I': return f.size == 1 ? as (std::int8_t ()) : f.size == 2 ? as (std::int16_t ())
                         : f.size == 4 ? as (std::int32_t ()) : as (std::int64_t ());
          default: return f.size == 1 ? as (std::uint8_t ()) : f.size == 2 ? as (std::uint16_t ())
                        : f.size == 4 ? as (std::uint32_t ()) : as (std::uint64_t ());
        }
      }

      /** The first field named \a name; requireConsistent() made sure x, y and z are there. */
      std::size_t
      fieldIndex (const PcdHeader& h, const char* name)
      {
        return static_cast<std::size_t> (std::find_if (h.fields.begin (), h.fields.end (),
                                                       [&] (const PcdField& f) { return f.name == name; }) - h.fields.begin ());
      }

      const PcdField&
      field (const PcdHeader& h, const char* name)
      {
        return h.fields[fieldIndex (h, name)];
      }

      [[noreturn]] void
      dataError (const std::string& path, const std::string& what)
      {
        PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' is not a valid PCD file: " << what);
      }

      /** DATA binary: the points one after the other, point_step bytes each. */
      void
      readBinary (std::string_view data, const PcdHeader& h, pcl::PointCloud<pcl::PointXYZ>& cloud, const std::string& path)
      {
        if (h.points > data.size () / h.point_step)
          dataError (path, std::to_string (h.points) + " points of " + std::to_string (h.point_step)
                     + " bytes need more than the " + std::to_string (data.size ()) + " bytes of data");
        const PcdField &fx = field (h, "x"), &fy = field (h, "y"), &fz = field (h, "z");
        cloud.resize (h.points);
        for (std::size_t i = 0; i < cloud.size (); ++i)
        {
          const char* point = data.data () + i * h.point_step;
          cloud[i] = pcl::PointXYZ (detail::toFloat (valueAt (point + fx.offset, fx)), detail::toFloat (valueAt (point + fy.offset, fy)),
                                    detail::toFloat (valueAt (point + fz.offset, fz)));
        }
      }

      /** DATA binary_compressed: compressed and uncompressed sizes, then LZF data that uncompresses to
        * each field's values for all points in turn (fields named "_", padding, are not stored). */
      void
      readCompressed (std::string_view data, const PcdHeader& h, pcl::PointCloud<pcl::PointXYZ>& cloud, const std::string& path)
      {
        std::uint32_t sizes[2] = {0, 0};  // in the machine's byte order, as PCL writes them
        if (data.size () < sizeof (sizes))
          dataError (path, "binary_compressed data without its sizes");
        // The stated size is 32 bits, and LZF expands at most about 100 times: this bounds the points
        // before anything is multiplied or allocated.
        const long double payload = static_cast<long double> (h.points) * h.point_step;
        if (payload > 4294967295.0L || payload > std::max (64.0L * (1 << 20), 1024.0L * data.size ()))
          dataError (path, std::to_string (h.points) + " points cannot be in " + std::to_string (data.size ()) + " bytes");
        std::memcpy (sizes, data.data (), sizeof (sizes));
        std::vector<std::size_t> block (h.fields.size (), 0);  // where each field's values start
        std::size_t expected = 0;
        for (std::size_t k = 0; k < h.fields.size (); ++k)
        {
          block[k] = expected;
          if (h.fields[k].name != "_")
            expected += h.fields[k].size * h.fields[k].count * h.points;
        }
        if (sizes[1] != expected)
          dataError (path, "the data uncompresses to " + std::to_string (sizes[1]) + " bytes; WIDTH x HEIGHT points take "
                     + std::to_string (expected));
        if (sizes[0] > data.size () - sizeof (sizes))
          dataError (path, "binary_compressed data cut short");
        std::vector<char> raw (expected);
        if (expected > 0 && !detail::lzfDecompress (reinterpret_cast<const unsigned char*> (data.data ()) + sizeof (sizes),
                                                    sizes[0], reinterpret_cast<unsigned char*> (raw.data ()), expected))
          dataError (path, "binary_compressed data that do not uncompress to their stated size");
        cloud.resize (h.points);
        const std::size_t kx = fieldIndex (h, "x"), ky = fieldIndex (h, "y"), kz = fieldIndex (h, "z");
        const auto value = [&] (std::size_t k, std::size_t i) {
          return detail::toFloat (valueAt (raw.data () + block[k] + i * h.fields[k].size, h.fields[k]));
        };
        for (std::size_t i = 0; i < cloud.size (); ++i)
          cloud[i] = pcl::PointXYZ (value (kx, i), value (ky, i), value (kz, i));
      }

      /** DATA ascii: a line per point, as many values as the fields' counts add up to. */
      void
      readAscii (std::string_view data, const PcdHeader& h, pcl::PointCloud<pcl::PointXYZ>& cloud, const std::string& path)
      {
        std::size_t per_point = 0;
        for (const auto& f : h.fields)
          per_point += f.count;
        if (h.points > data.size () / (2 * per_point))  // a value and a separator at the least
          dataError (path, std::to_string (h.points) + " points cannot fit in " + std::to_string (data.size ()) + " bytes");
        std::size_t column[3] = {0, 0, 0};  // of x, y and z among a line's values
        const char* axes[3] = {"x", "y", "z"};
        for (int a = 0; a < 3; ++a)
          for (std::size_t k = 0; k < fieldIndex (h, axes[a]); ++k)
            column[a] += h.fields[k].count;
        cloud.resize (h.points);
        detail::ByteStream lines (data);
        std::string line;
        for (std::size_t i = 0; i < cloud.size ();)
        {
          if (!std::getline (lines, line))
            dataError (path, "the data end after " + std::to_string (i) + " of " + std::to_string (h.points) + " points");
          std::istringstream words (line);
          std::vector<std::string> values;
          for (std::string v; words >> v;)
            values.push_back (v);
          if (values.empty ())
            continue;
          if (values.size () != per_point)
            dataError (path, "point " + std::to_string (i) + " has " + std::to_string (values.size ()) + " values, not "
                       + std::to_string (per_point));
          float xyz[3];
          for (int a = 0; a < 3; ++a)
          {
            const std::string& v = values[column[a]];
            if (!detail::parseFloat (v.data (), v.data () + v.size (), xyz[a]))
              dataError (path, "bad number '" + v + "'");
          }
          cloud[i++] = pcl::PointXYZ (xyz[0], xyz[1], xyz[2]);
        }
      }

    }

    void
    readRangePCD (const std::string& path, pcl::PointCloud<pcl::PointXYZ>& cloud)
    {
      const std::string bytes = detail::readFile (path);
      detail::ByteStream file (bytes);
      const PcdHeader header = parseHeader (file, path);
      const std::string_view data = file.rest ();
      pcl::PointCloud<pcl::PointXYZ> out;
      if (header.points > 0)
      {
        if (header.data == PcdData::Ascii)
          readAscii (data, header, out, path);
        else if (header.data == PcdData::Binary)
          readBinary (data, header, out, path);
        else
          readCompressed (data, header, out, path);
      }
      out.width = static_cast<std::uint32_t> (header.width);
      out.height = static_cast<std::uint32_t> (header.height);
      if (header.points == 0)
        out.width = out.height = 0;
      out.sensor_origin_ = header.origin;
      out.sensor_orientation_ = header.orientation;
      updateDenseFlag (out);
      cloud.swap (out);
    }
  }
}
