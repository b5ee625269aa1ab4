/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/ascii_range_ply.h>
#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>

#include <charconv>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <vector>

namespace pcl
{
  namespace io
  {
    namespace
    {
      struct PlyProperty
      {
        std::string name;
        bool is_list = false;
      };

      struct PlyElement
      {
        std::string name;
        std::size_t count = 0;
        std::vector<PlyProperty> properties;
      };

      struct PlyHeader
      {
        bool ascii = false;
        std::vector<PlyElement> elements;
        std::size_t num_cols = 0, num_rows = 0;
      };

      /** The header's lines up to end_header, read from \a in, which is left at the body; false when
        * it is not a PLY header at all. */
      bool
      parseHeader (std::istream& in, PlyHeader& header)
      {
        std::string line;
        if (!std::getline (in, line) || line.rfind ("ply", 0) != 0)
          return false;
        while (std::getline (in, line))
        {
          std::istringstream words (line);
          std::string key;
          words >> key;
          if (key == "format")
          {
            std::string format;
            words >> format;
            header.ascii = (format == "ascii");
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
              return false;
            header.elements.push_back (e);
          }
          else if (key == "property")
          {
            if (header.elements.empty ())
              return false;
            PlyProperty p;
            std::string type;
            words >> type;
            p.is_list = (type == "list");
            if (p.is_list)
              words >> type >> type;  // count type, item type
            words >> p.name;
            header.elements.back ().properties.push_back (p);
          }
          else if (key == "end_header")
            return true;
        }
        return false;
      }

      /** std::isspace without its locale look-up, for the tight token loop. */
      inline bool
      isSpace (char c)
      {
        return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\v' || c == '\f';
      }

      /** Whitespace-separated tokens of the body, read in order. */
      class Tokens
      {
        public:
          Tokens (const char* begin, const char* end, const std::string& path) : p_ (begin), end_ (end), path_ (path) {}

          float
          nextFloat ()
          {
            const auto [first, last] = next ();
            float value = 0.0f;
            // from_chars does not accept a leading '+', which some writers emit.
            const char* start = (first != last && *first == '+') ? first + 1 : first;
            const auto result = std::from_chars (start, last, value);
            if (result.ec == std::errc::result_out_of_range)
              return parseOutOfRange (start, last);
            if (result.ec != std::errc () || result.ptr != last)
              fail ("bad number '" + std::string (first, last) + "'");
            return value;
          }

          long long
          nextInteger ()
          {
            const auto [first, last] = next ();
            long long value = 0;
            const auto result = std::from_chars (first, last, value);
            if (result.ec != std::errc () || result.ptr != last)
              fail ("bad integer '" + std::string (first, last) + "'");
            return value;
          }

          void
          skip () { next (); }

          /** Skip one list property: its count, then that many items. */
          long long
          skipList ()
          {
            const long long n = nextInteger ();
            if (n < 0)
              fail ("negative list length");
            for (long long i = 0; i < n; ++i)
              skip ();
            return n;
          }

          [[noreturn]] void
          fail (const std::string& what) const
          {
            PCL_TENSOR_THROW (pcl::IOException, "'" << path_ << "' is not a valid ASCII PLY file: " << what);
          }

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

          /** Denormals and overflow: keep what a strtod-based reader would give. */
          static float
          parseOutOfRange (const char* first, const char* last)
          {
            const double value = std::strtod (std::string (first, last).c_str (), nullptr);
            return static_cast<float> (value);
          }

          const char* p_;
          const char* end_;
          const std::string& path_;
      };

      int
      propertyIndex (const PlyElement& e, const std::string& name)
      {
        for (std::size_t i = 0; i < e.properties.size (); ++i)
          if (e.properties[i].name == name && !e.properties[i].is_list)
            return static_cast<int> (i);
        return -1;
      }

      void
      readVertices (Tokens& tokens, const PlyElement& e, pcl::PointCloud<pcl::PointXYZ>& vertices)
      {
        const int ix = propertyIndex (e, "x"), iy = propertyIndex (e, "y"), iz = propertyIndex (e, "z");
        if (ix < 0 || iy < 0 || iz < 0)
          tokens.fail ("the vertex element has no x, y and z");
        vertices.resize (e.count);
        for (auto& v : vertices)
          for (int k = 0; k < static_cast<int> (e.properties.size ()); ++k)
          {
            if (e.properties[k].is_list)
              tokens.skipList ();
            else if (k == ix)
              v.x = tokens.nextFloat ();
            else if (k == iy)
              v.y = tokens.nextFloat ();
            else if (k == iz)
              v.z = tokens.nextFloat ();
            else
              tokens.skip ();
          }
      }

      /** range_grid: per cell, a list of the vertices seen there (Stanford scans list 0 or 1). */
      std::vector<long long>
      readGrid (Tokens& tokens, const PlyElement& e, std::size_t vertex_count)
      {
        if (e.properties.size () != 1 || !e.properties[0].is_list)
          tokens.fail ("range_grid must hold one list property");
        std::vector<long long> cells (e.count, -1);
        for (auto& cell : cells)
        {
          const long long n = tokens.nextInteger ();
          if (n < 0)
            tokens.fail ("negative list length");
          for (long long i = 0; i < n; ++i)
          {
            const long long index = tokens.nextInteger ();
            if (index < 0 || static_cast<std::size_t> (index) >= vertex_count)
              tokens.fail ("range_grid names vertex " + std::to_string (index) + " of " + std::to_string (vertex_count));
            if (i == 0)
              cell = index;
          }
        }
        return cells;
      }

      void
      skipElement (Tokens& tokens, const PlyElement& e)
      {
        for (std::size_t i = 0; i < e.count; ++i)
          for (const auto& p : e.properties)
            if (p.is_list)
              tokens.skipList ();
            else
              tokens.skip ();
      }

      void
      fillGrid (const pcl::PointCloud<pcl::PointXYZ>& vertices, const std::vector<long long>& cells,
                const PlyHeader& header, pcl::PointCloud<pcl::PointXYZ>& cloud)
      {
        const float nan = std::numeric_limits<float>::quiet_NaN ();
        cloud.resize (header.num_cols * header.num_rows);
        cloud.width = static_cast<std::uint32_t> (header.num_cols);
        cloud.height = static_cast<std::uint32_t> (header.num_rows);
        for (std::size_t i = 0; i < cells.size (); ++i)
          cloud[i] = cells[i] < 0 ? pcl::PointXYZ (nan, nan, nan) : vertices[cells[i]];
      }

      bool
      allFinite (const pcl::PointCloud<pcl::PointXYZ>& cloud)
      {
        for (const auto& p : cloud)
          if (!pcl::isXYZFinite (p))
            return false;
        return true;
      }
    }

    bool
    readAsciiRangePLY (const std::string& path, pcl::PointCloud<pcl::PointXYZ>& cloud)
    {
      std::ifstream file (path, std::ios::binary);
      if (!file)
        PCL_TENSOR_THROW (pcl::IOException, "cannot open '" << path << "'");
      PlyHeader header;
      if (!parseHeader (file, header) || !header.ascii)
        return false;  // binary files are left to pcl::PLYReader before their body is read
      const std::string text ((std::istreambuf_iterator<char> (file)), std::istreambuf_iterator<char> ());

      pcl::PointCloud<pcl::PointXYZ> vertices;
      std::vector<long long> cells;
      bool has_vertices = false, has_grid = false;
      Tokens tokens (text.data (), text.data () + text.size (), path);
      for (const auto& e : header.elements)
        if (e.count > text.size ())  // each instance takes at least one byte: refuse before allocating
          tokens.fail ("element " + e.name + " claims " + std::to_string (e.count) + " instances");
        else if (e.name == "vertex" && !has_vertices)
        {
          readVertices (tokens, e, vertices);
          has_vertices = true;
        }
        else if (e.name == "range_grid" && has_vertices && !has_grid)
        {
          cells = readGrid (tokens, e, vertices.size ());
          has_grid = true;
        }
        else
          skipElement (tokens, e);
      if (!has_vertices)
        tokens.fail ("no vertex element");

      if (has_grid && (header.num_cols * header.num_rows != cells.size () || header.num_rows < 2))
        return false;  // a grid without a size that fits it: leave the interpretation to pcl::PLYReader
      pcl::PointCloud<pcl::PointXYZ> out;
      if (has_grid)
        fillGrid (vertices, cells, header, out);
      else
        out.swap (vertices);
      out.is_dense = allFinite (out);
      cloud.swap (out);
      return true;
    }
  }
}
