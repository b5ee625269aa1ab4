/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/view_pairs_io.h>
#include "file_input.h"
#include <pcl/common/tensor_exceptions.h>

#include <sstream>

namespace pcl
{
  namespace io
  {
    namespace
    {
      std::string
      lastComponent (const std::string& path)
      {
        const auto slash = path.find_last_of ("/\\");
        return slash == std::string::npos ? path : path.substr (slash + 1);
      }

      /** The index of the view \a entry names, or -1. An exact name wins over a last-component match. */
      int
      viewIndex (const std::string& entry, const std::vector<std::string>& names)
      {
        for (std::size_t i = 0; i < names.size (); ++i)
          if (names[i] == entry)
            return static_cast<int> (i);
        int found = -1;
        for (std::size_t i = 0; i < names.size (); ++i)
          if (lastComponent (names[i]) == lastComponent (entry))
          {
            if (found >= 0)
              return -1;  // ambiguous: two views share the name
            found = static_cast<int> (i);
          }
        if (found >= 0)
          return found;
        std::size_t used = 0;
        int index = -1;
        try
        {
          index = std::stoi (entry, &used);
        }
        catch (const std::exception&)
        {
          return -1;
        }
        return (used == entry.size () && index >= 0 && index < static_cast<int> (names.size ())) ? index : -1;
      }
    }

    std::vector<std::pair<int, int>>
    loadViewPairs (const std::string& path, const std::vector<std::string>& view_names)
    {
      std::istringstream file (detail::readFile (path));
      std::vector<std::pair<int, int>> pairs;
      std::string line;
      for (int number = 1; std::getline (file, line); ++number)
      {
        std::istringstream words (line);
        std::string a, b, extra;
        if (!(words >> a) || a[0] == '#')
          continue;
        if (!(words >> b) || (words >> extra))
          detail::throwAtLine (path, number, "expected two views per line, got '" + line + "'");
        const int i = viewIndex (a, view_names), j = viewIndex (b, view_names);
        if (i < 0 || j < 0)
          detail::throwAtLine (path, number, "'" + (i < 0 ? a : b) + "' is neither a view's index nor (unambiguously) its file name");
        if (i == j)
          detail::throwAtLine (path, number, "a view cannot be paired with itself");
        pairs.emplace_back (i, j);
      }
      return pairs;
    }
  }
}
