/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/range_ply.h>
#include "ascii_number.h"
#include "file_input.h"
#include <pcl/io/range_scan_io.h>  // updateDenseFlag
#include <pcl/common/tensor_exceptions.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <string_view>
#include <vector>

namespace pcl
{
  namespace io
  {
    namespace
    {
      enum class PlyType : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

      /** PLY's scalar type names, the original ones (char, uchar, ...) and the sized ones (int8, ...). */
      bool
      parseType (const std::string& name, PlyType& type)
      {
        static const std::pair<const char*, PlyType> names[] = {
          {"char", PlyType::Int8},     {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
          {"uint8", PlyType::UInt8},   {"short", PlyType::Int16},     {"int16", PlyType::Int16},
          {"ushort", PlyType::UInt16}, {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
          {"int32", PlyType::Int32},   {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
          {"float", PlyType::Float32}, {"float32", PlyType::Float32}, {"double", PlyType::Float64},
          {"float64", PlyType::Float64}};
        for (const auto& [n, t] : names)
          if (name == n)
          {
            type = t;
            return true;
          }
        return false;
      }

      std::size_t
      sizeOf (PlyType type)
      {
        switch (type)
        {
          case PlyType::Int8: case PlyType::UInt8: return 1;
          case PlyType::Int16: case PlyType::UInt16: return 2;
          case PlyType::Int32: case PlyType::UInt32: case PlyType::Float32: return 4;
          case PlyType::Float64: return 8;
        }
        return 0;
      }

      bool
      isIntegral (PlyType type)
      {
        return type != PlyType::Float32 && type != PlyType::Float64;
      }

      struct PlyProperty
      {
        std::string name;
        PlyType type = PlyType::Float32;
        bool is_list = false;
        PlyType count_type = PlyType::UInt8;  ///< of a list's length
      };

      struct PlyElement
      {
        std::string name;
        std::size_t count = 0;
        std::vector<PlyProperty> properties;
      };

      enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

      struct PlyHeader
      {
        PlyFormat format = PlyFormat::Ascii;
        std::vector<PlyElement> elements;
        std::size_t num_cols = 0, num_rows = 0;  ///< obj_info: the size of the range grid
      };

      PlyFormat
      parseFormat (std::istringstream& words, const std::string& path, int line_no)
      {
        std::string format, version;
        words >> format >> version;
        if (version != "1.0")
          detail::throwAtLine (path, line_no, "PLY version '" + version + "' is not 1.0");
        if (format == "ascii")
          return PlyFormat::Ascii;
        if (format == "binary_little_endian")
          return PlyFormat::BinaryLittleEndian;
        if (format == "binary_big_endian")
          return PlyFormat::BinaryBigEndian;
        detail::throwAtLine (path, line_no, "unknown PLY format '" + format + "'");
      }

      PlyProperty
      parseProperty (std::istringstream& words, const std::string& path, int line_no)
      {
        PlyProperty p;
        std::string type;
        words >> type;
        p.is_list = (type == "list");
        if (p.is_list)
        {
          std::string count_type;
          words >> count_type >> type;
          if (!parseType (count_type, p.count_type) || !isIntegral (p.count_type))
            detail::throwAtLine (path, line_no, "a list whose length type is '" + count_type + "'");
        }
        if (!parseType (type, p.type))
          detail::throwAtLine (path, line_no, "unknown property type '" + type + "'");
        if (!(words >> p.name))
          detail::throwAtLine (path, line_no, "a property without a name");
        return p;
      }

      /** The header's lines up to end_header, read from \a in, which is left at the body. */
      PlyHeader
      parseHeader (std::istream& in, const std::string& path)
      {
        std::string line;
        if (!std::getline (in, line) || line.rfind ("ply", 0) != 0 || line.find_first_not_of ('\r', 3) != std::string::npos)
          PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' does not start with the PLY magic line");
        PlyHeader header;
        bool has_format = false;
        for (int line_no = 2; std::getline (in, line); ++line_no)
        {
          std::istringstream words (line);
          std::string key;
          words >> key;
          if (key == "format")
          {
            header.format = parseFormat (words, path, line_no);
            has_format = true;
          }
          else if (key == "obj_info")
          {
            std::string what;
            words >> what;
            if (what == "num_cols")
              words >> header.num_cols;
            else if (what == "num_rows")
              words >> header.num_rows;
          }
          else if (key == "element")
          {
            PlyElement e;
            if (!(words >> e.name >> e.count))
              detail::throwAtLine (path, line_no, "an element without a name and a count");
            header.elements.push_back (e);
          }
          else if (key == "property")
          {
            if (header.elements.empty ())
              detail::throwAtLine (path, line_no, "a property before any element");
            header.elements.back ().properties.push_back (parseProperty (words, path, line_no));
          }
          else if (key == "end_header")
          {
            if (!has_format)
              PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' has no format line");
            return header;
          }
        }
        PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' has no end_header line");
      }

      /** std::isspace without its locale look-up, for the tight token loop. */
      inline bool
      isSpace (char c)
      {
        return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\v' || c == '\f';
      }

      /** Where the reading of a body is, and how it fails. */
      class BodyCursor
      {
        public:
          BodyCursor (const char* begin, const char* end, const std::string& path, const char* format)
            : p_ (begin), end_ (end), path_ (path), format_ (format) {}

          std::size_t
          remaining () const { return static_cast<std::size_t> (end_ - p_); }

          [[noreturn]] void
          fail (const std::string& what) const
          {
            PCL_TENSOR_THROW (pcl::IOException, "'" << path_ << "' is not a valid " << format_ << " PLY file: " << what);
          }

        protected:
          const char* p_;
          const char* end_;

        private:
          const std::string& path_;
          const char* format_;
      };

      /** The body of an ASCII PLY file: whitespace-separated tokens, read in order. */
      class AsciiBody : public BodyCursor
      {
        public:
          AsciiBody (const char* begin, const char* end, const std::string& path) : BodyCursor (begin, end, path, "ASCII") {}

          float
          readFloat (PlyType)
          {
            const auto [first, last] = next ();
            float value = 0.0f;
            if (!detail::parseFloat (first, last, value))
              fail ("bad number '" + std::string (first, last) + "'");
            return value;
          }

          long long
          readInteger (PlyType)
          {
            const auto [first, last] = next ();
            long long value = 0;
            const auto result = std::from_chars (first, last, value);
            if (result.ec != std::errc () || result.ptr != last)
              fail ("bad integer '" + std::string (first, last) + "'");
            return value;
          }

          void
          skipValue (PlyType) { next (); }

          /** A lower bound on the bytes one instance of \a e takes: a token per property. */
          static std::size_t
          minimumBytes (const PlyElement& e) { return e.properties.size (); }

        private:
          std::pair<const char*, const char*>
          next ()
          {
            while (p_ != end_ && isSpace (*p_))
              ++p_;
            if (p_ == end_)
              fail ("truncated");
            const char* first = p_;
            while (p_ != end_ && !isSpace (*p_))
              ++p_;
            return {first, p_};
          }
      };

      /** The body of a binary PLY file: packed values of the header's types, in either byte order. */
      class BinaryBody : public BodyCursor
      {
        public:
          BinaryBody (const char* begin, const char* end, bool swap_bytes, const std::string& path)
            : BodyCursor (begin, end, path, "binary"), swap_ (swap_bytes) {}

          float
          readFloat (PlyType type) { return detail::toFloat (read (type)); }

          long long
          readInteger (PlyType type)
          {
            if (!isIntegral (type))
              fail ("a floating-point value where an integer is needed");
            return static_cast<long long> (read (type));
          }

          void
          skipValue (PlyType type) { take (sizeOf (type)); }

          /** The bytes one instance of \a e takes at least: its scalars and the lengths of its lists. */
          static std::size_t
          minimumBytes (const PlyElement& e)
          {
            std::size_t bytes = 0;
            for (const auto& p : e.properties)
              bytes += sizeOf (p.is_list ? p.count_type : p.type);
            return bytes;
          }

        private:
          const char*
          take (std::size_t bytes)
          {
            if (remaining () < bytes)
              fail ("truncated");
            const char* at = p_;
            p_ += bytes;
            return at;
          }

          template <typename T> static double
          as (const unsigned char* bytes)
          {
            T value;
            std::memcpy (&value, bytes, sizeof (T));
            return static_cast<double> (value);
          }

          /** Every PLY scalar fits a double exactly, so one conversion serves all types. */
          double
          read (PlyType type)
          {
            const std::size_t n = sizeOf (type);
            unsigned char bytes[8] = {};
            std::memcpy (bytes, take (n), n);
            if (swap_)
              std::reverse (bytes, bytes + n);
            switch (type)
            {
              case PlyType::Int8: return as<std::int8_t> (bytes);
              case PlyType::UInt8: return as<std::uint8_t> (bytes);
              case PlyType::Int16: return as<std::int16_t> (bytes);
              case PlyType::UInt16: return as<std::uint16_t> (bytes);
              case PlyType::Int32: return as<std::int32_t> (bytes);
              case PlyType::UInt32: return as<std::uint32_t> (bytes);
              case PlyType::Float32: return as<float> (bytes);
              case PlyType::Float64: return as<double> (bytes);
            }
            return 0.0;
          }

          bool swap_;
      };

      template <typename Body> long long
      listLength (Body& body, const PlyProperty& p)
      {
        const long long n = body.readInteger (p.count_type);
        if (n < 0)
          body.fail ("negative list length");
        return n;
      }

      /** Skipping a list reads its items one by one, so a wrong length fails at the end of the data
        * instead of jumping past it. */
      template <typename Body> void
      skipProperty (Body& body, const PlyProperty& p)
      {
        const long long n = p.is_list ? listLength (body, p) : 1;
        for (long long i = 0; i < n; ++i)
          body.skipValue (p.type);
      }

      template <typename Body> void
      skipElement (Body& body, const PlyElement& e)
      {
        for (std::size_t i = 0; i < e.count; ++i)
          for (const auto& p : e.properties)
            skipProperty (body, p);
      }

      int
      scalarIndex (const PlyElement& e, const std::string& name)
      {
        for (std::size_t i = 0; i < e.properties.size (); ++i)
          if (e.properties[i].name == name && !e.properties[i].is_list)
            return static_cast<int> (i);
        return -1;
      }

      template <typename Body> void
      readVertices (Body& body, const PlyElement& e, pcl::PointCloud<pcl::PointXYZ>& vertices)
      {
        const int ix = scalarIndex (e, "x"), iy = scalarIndex (e, "y"), iz = scalarIndex (e, "z");
        if (ix < 0 || iy < 0 || iz < 0)
          body.fail ("the vertex element has no x, y and z");
        vertices.resize (e.count);
        for (auto& v : vertices)
          for (int k = 0; k < static_cast<int> (e.properties.size ()); ++k)
          {
            const PlyProperty& p = e.properties[k];
            if (k == ix)
              v.x = body.readFloat (p.type);
            else if (k == iy)
              v.y = body.readFloat (p.type);
            else if (k == iz)
              v.z = body.readFloat (p.type);
            else
              skipProperty (body, p);
          }
      }

      /** range_grid: per cell, a list of the vertices seen there (Stanford scans list 0 or 1); a cell
        * keeps the first, -1 when empty. */
      template <typename Body> std::vector<long long>
      readGrid (Body& body, const PlyElement& e, std::size_t vertex_count)
      {
        if (e.properties.size () != 1 || !e.properties[0].is_list)
          body.fail ("range_grid must hold one list property");
        const PlyProperty& p = e.properties[0];
        std::vector<long long> cells (e.count, -1);
        for (auto& cell : cells)
        {
          const long long n = listLength (body, p);
          for (long long i = 0; i < n; ++i)
          {
            const long long index = body.readInteger (p.type);
            if (index < 0 || static_cast<std::size_t> (index) >= vertex_count)
              body.fail ("range_grid names vertex " + std::to_string (index) + " of " + std::to_string (vertex_count));
            if (i == 0)
              cell = index;
          }
        }
        return cells;
      }

      /** What the file holds: its vertices and the two ways it can say they form a grid. */
      struct PlyContent
      {
        pcl::PointCloud<pcl::PointXYZ> vertices;
        bool has_grid = false;
        std::vector<long long> cells;                      ///< range_grid: a vertex per cell, -1 when empty
        long long viewport_width = 0, viewport_height = 0;  ///< camera element (pcl::PLYWriter)
      };

      /** The camera element pcl::PLYWriter writes: the organized cloud's size is its viewport. */
      template <typename Body> void
      readCamera (Body& body, const PlyElement& e, PlyContent& content)
      {
        for (std::size_t i = 0; i < e.count; ++i)
          for (const auto& p : e.properties)
            if (!p.is_list && isIntegral (p.type) && (p.name == "viewportx" || p.name == "viewporty"))
              (p.name == "viewportx" ? content.viewport_width : content.viewport_height) = body.readInteger (p.type);
            else
              skipProperty (body, p);
      }

      template <typename Body> PlyContent
      readBody (Body& body, const PlyHeader& header)
      {
        PlyContent content;
        bool has_vertices = false;
        for (const auto& e : header.elements)
        {
          // Refuse a count the data cannot hold before allocating for it.
          const std::size_t bytes = Body::minimumBytes (e);
          if (bytes > 0 && e.count > body.remaining () / bytes)
            body.fail ("element " + e.name + " claims " + std::to_string (e.count) + " instances");
          if (e.name == "vertex" && has_vertices)
            body.fail ("more than one vertex element");
          if (e.name == "vertex")
          {
            readVertices (body, e, content.vertices);
            has_vertices = true;
          }
          else if (e.properties.empty ())
            continue;  // no data to read, however large the count: looping over it would hang
          else if (e.name == "range_grid" && has_vertices && !content.has_grid)
          {
            content.cells = readGrid (body, e, content.vertices.size ());
            content.has_grid = true;
          }
          else if (e.name == "camera")
            readCamera (body, e, content);
          else
            skipElement (body, e);
        }
        if (!has_vertices)
          body.fail ("no vertex element");
        return content;
      }

      /** Whether cols x rows (from the file, so unchecked) is a grid of at least two rows with \a cells cells. */
      bool
      isGridOf (unsigned long long cols, unsigned long long rows, std::size_t cells)
      {
        return cols > 0 && rows >= 2 && cells % cols == 0 && cells / cols == rows;
      }

      void
      organize (PlyContent& content, const PlyHeader& header, pcl::PointCloud<pcl::PointXYZ>& cloud)
      {
        if (content.has_grid && isGridOf (header.num_cols, header.num_rows, content.cells.size ()))
        {
          const float nan = std::numeric_limits<float>::quiet_NaN ();
          cloud.resize (content.cells.size ());
          cloud.width = static_cast<std::uint32_t> (header.num_cols);
          cloud.height = static_cast<std::uint32_t> (header.num_rows);
          for (std::size_t i = 0; i < content.cells.size (); ++i)
            cloud[i] = content.cells[i] < 0 ? pcl::PointXYZ (nan, nan, nan) : content.vertices[content.cells[i]];
          return;
        }
        cloud.swap (content.vertices);
        if (content.viewport_width > 0 && content.viewport_height > 0 &&
            isGridOf (static_cast<unsigned long long> (content.viewport_width),
                      static_cast<unsigned long long> (content.viewport_height), cloud.size ()))
        {
          cloud.width = static_cast<std::uint32_t> (content.viewport_width);
          cloud.height = static_cast<std::uint32_t> (content.viewport_height);
        }
      }


      bool
      isLittleEndianMachine ()
      {
        const std::uint16_t one = 1;
        unsigned char first = 0;
        std::memcpy (&first, &one, 1);
        return first == 1;
      }
    }

    void
    readRangePLY (const std::string& path, pcl::PointCloud<pcl::PointXYZ>& cloud)
    {
      const std::string bytes = detail::readFile (path);
      detail::ByteStream file (bytes);
      const PlyHeader header = parseHeader (file, path);
      const std::string_view data = file.rest ();
      const char* begin = data.data ();
      const char* end = begin + data.size ();

      PlyContent content;
      if (header.format == PlyFormat::Ascii)
      {
        AsciiBody body (begin, end, path);
        content = readBody (body, header);
      }
      else
      {
        const bool little = (header.format == PlyFormat::BinaryLittleEndian);
        BinaryBody body (begin, end, little != isLittleEndianMachine (), path);
        content = readBody (body, header);
      }
      pcl::PointCloud<pcl::PointXYZ> out;
      organize (content, header, out);
      updateDenseFlag (out);
      cloud.swap (out);
    }
  }
}
