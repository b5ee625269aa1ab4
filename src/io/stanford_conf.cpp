/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/stanford_conf.h>
#include "file_input.h"
#include <pcl/common/tensor_exceptions.h>

#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace pcl
{
  namespace io
  {
    Eigen::Affine3d
    StanfordConfEntry::pose () const
    {
      Eigen::Affine3d p = Eigen::Affine3d::Identity ();
      p.linear () = quaternion.normalized ().toRotationMatrix ().transpose ();
      p.translation () = translation;
      return p;
    }

    StanfordConfEntry
    StanfordConfEntry::fromPose (const std::string& file, const Eigen::Affine3d& scan_to_world)
    {
      StanfordConfEntry e;
      e.file = file;
      e.translation = scan_to_world.translation ();
      // R(q)^T is the pose's rotation, so q is the conjugate of the rotation's quaternion.
      e.quaternion = Eigen::Quaterniond (scan_to_world.rotation ()).conjugate ();
      return e;
    }

    namespace
    {
      StanfordConfEntry
      parseBmesh (std::istringstream& in, const std::string& path, int line_no)
      {
        StanfordConfEntry e;
        double qx, qy, qz, qw;
        std::string extra;
        if (!(in >> e.file >> e.translation.x () >> e.translation.y () >> e.translation.z () >> qx >> qy >> qz >> qw)
            || (in >> extra))
          detail::throwAtLine (path, line_no, "a bmesh line needs FILE tx ty tz qx qy qz qw");
        e.quaternion = Eigen::Quaterniond (qw, qx, qy, qz);
        // An infinite or overflowing quaternion would normalize to NaN: a rotation must come out.
        const double norm = e.quaternion.norm ();
        if (!(norm > 0.0) || !std::isfinite (norm) || !e.translation.allFinite ())
          detail::throwAtLine (path, line_no, "invalid pose");
        return e;
      }
    }

    std::vector<StanfordConfEntry>
    loadStanfordConf (const std::string& path)
    {
      std::istringstream file (detail::readFile (path));
      std::vector<StanfordConfEntry> entries;
      std::string line;
      for (int line_no = 1; std::getline (file, line); ++line_no)
      {
        std::istringstream in (line);
        std::string keyword;
        if (!(in >> keyword) || keyword[0] == '#' || keyword == "camera" || keyword == "mesh")
          continue;
        if (keyword != "bmesh")
          detail::throwAtLine (path, line_no, "unknown keyword '" + keyword + "'");
        entries.push_back (parseBmesh (in, path, line_no));
      }
      return entries;
    }

    bool
    isStanfordConfFileName (const std::string& file)
    {
      return !file.empty () && file.find_first_of (" \t\r\n\v\f") == std::string::npos;
    }

    namespace
    {
      std::string
      fileName (const std::string& path)
      {
        const auto slash = path.find_last_of ("/\\");
        return slash == std::string::npos ? path : path.substr (slash + 1);
      }

      /** Name -> index of \a names by file name, refusing a name given twice. */
      std::map<std::string, int>
      indexByFileName (const std::vector<std::string>& names, const char* what)
      {
        std::map<std::string, int> index;
        for (std::size_t i = 0; i < names.size (); ++i)
          if (!index.emplace (fileName (names[i]), static_cast<int> (i)).second)
            PCL_TENSOR_THROW (pcl::BadArgumentException, "two " << what << " are named '" << fileName (names[i])
                              << "': a .conf pose could belong to either");
        return index;
      }
    }

    std::vector<int>
    confEntriesOfFiles (const std::vector<StanfordConfEntry>& entries, const std::vector<std::string>& files)
    {
      std::vector<std::string> entry_names;
      for (const auto& e : entries)
        entry_names.push_back (e.file);
      const std::map<std::string, int> entry_of = indexByFileName (entry_names, ".conf entries");
      std::vector<int> matched (files.size (), -1);
      std::map<int, std::size_t> file_of;
      for (std::size_t i = 0; i < files.size (); ++i)
      {
        const auto it = entry_of.find (fileName (files[i]));
        if (it == entry_of.end ())
          continue;
        if (!file_of.emplace (it->second, i).second)
          PCL_TENSOR_THROW (pcl::BadArgumentException, "two views are named '" << it->first << "': the .conf pose of that "
                            "name could belong to either");
        matched[i] = it->second;
      }
      return matched;
    }

    void
    saveStanfordConf (const std::string& path, const std::vector<StanfordConfEntry>& entries)
    {
      std::ostringstream out;
      out.precision (std::numeric_limits<double>::max_digits10);
      for (const auto& e : entries)
      {
        if (!isStanfordConfFileName (e.file))
          PCL_TENSOR_THROW (pcl::IOException, "cannot write '" << e.file << "' into a .conf file: empty or white space");
        const auto& t = e.translation;
        const auto& q = e.quaternion;
        out << "bmesh " << e.file << ' ' << t.x () << ' ' << t.y () << ' ' << t.z () << ' '
            << q.x () << ' ' << q.y () << ' ' << q.z () << ' ' << q.w () << '\n';
      }
      std::ofstream file (path);
      if (!(file << out.str ()) || !file.flush ())
        PCL_TENSOR_THROW (pcl::IOException, "cannot write '" << path << "'");
    }
  }
}
