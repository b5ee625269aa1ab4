/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace pcl
{
  namespace io
  {
    /** \brief One `bmesh FILE tx ty tz qx qy qz qw` line of a Stanford .conf file: the pose of one scan.
      *
      * The Stanford convention maps scan points into the common (world) frame by
      * p_world = R(q)^T * p_scan + t. The numbers are kept exactly as read, so that writing them back
      * reproduces them bit for bit.
      * \ingroup io
      */
    struct StanfordConfEntry
    {
      /** \brief The scan's file name, as written in the .conf (relative to the .conf's folder). */
      std::string file;
      /** \brief t. */
      Eigen::Vector3d translation = Eigen::Vector3d::Zero ();
      /** \brief q = (qx, qy, qz, qw), not necessarily normalized in the file; normalized when used. */
      Eigen::Quaterniond quaternion = Eigen::Quaterniond::Identity ();

      /** \brief The pose mapping scan points into the world frame: p_world = R(q)^T * p + t. */
      Eigen::Affine3d pose () const;

      /** \brief The entry whose pose() is \a scan_to_world (its rotation part must be a rotation). */
      static StanfordConfEntry
      fromPose (const std::string& file, const Eigen::Affine3d& scan_to_world);
    };

    /** \brief Read the bmesh lines of a Stanford .conf file; `camera` and `mesh` lines, blank lines and
      * lines starting with '#' are ignored.
      * \throw pcl::IOException when the file cannot be read, a line has an unknown keyword, or a bmesh
      * line does not hold a name and seven finite numbers with a non-zero quaternion (the message gives
      * the line number)
      */
    std::vector<StanfordConfEntry>
    loadStanfordConf (const std::string& path);

    /** \brief True when \a file can be named in a bmesh line: not empty, without white space. */
    bool
    isStanfordConfFileName (const std::string& file);

    /** \brief For each of \a files, the index of the entry that names it, or -1: entries and files are
      * matched by their names without folders, as pcl_tensor_model writes a .conf of its views.
      * \throw pcl::BadArgumentException when two entries have the same name, or two files the name of an
      * entry (which one a pose belongs to would be a guess)
      */
    std::vector<int>
    confEntriesOfFiles (const std::vector<StanfordConfEntry>& entries, const std::vector<std::string>& files);

    /** \brief Write entries as bmesh lines, with enough digits (max_digits10) that loadStanfordConf()
      * gives back the same doubles.
      * \throw pcl::IOException when the file cannot be written or a file name contains white space
      */
    void
    saveStanfordConf (const std::string& path, const std::vector<StanfordConfEntry>& entries);
  }
}
