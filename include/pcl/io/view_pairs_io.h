/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace pcl
{
  namespace io
  {
    /** \brief Read a list of overlapping view pairs: one pair per line, "A B", where each of A and B
      * is either a view's 0-based index or its file name (as given, or just its last path component).
      * Blank lines and lines starting with '#' are ignored.
      * \param[in] path the pairs file
      * \param[in] view_names the views' file names, in the order their indices refer to
      * \return the pairs as indices into \a view_names (a pair of a view with itself is refused)
      * \throw pcl::IOException when the file cannot be read, a line does not hold two entries, or an
      *        entry names no view or the same view twice (the message gives the line number)
      * \ingroup io
      */
    std::vector<std::pair<int, int>>
    loadViewPairs (const std::string& path, const std::vector<std::string>& view_names);
  }
}
