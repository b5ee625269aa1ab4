/*
 * pcl_tensor: tests of the Stanford .conf reader and writer (p_world = R(q)^T p + t).
 */
#include "test_utils.h"

#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/io/range_scan_io.h>
#include <pcl/io/scan_mesh_io.h>
#include <pcl/io/stanford_conf.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/surface/range_scan_triangulation.h>

#include <algorithm>
#include <iostream>

#include <cstdio>
#include <fstream>
#include <random>

namespace
{
  /** Median distance from the scan's finite points, mapped by \a pose, to the nearest model vertex. */
  double
  medianDistance (const pcl::PointCloud<pcl::PointXYZ>& scan, const Eigen::Affine3d& pose,
                  const pcl::KdTreeFLANN<pcl::PointXYZ>& model)
  {
    std::vector<double> d;
    pcl::Indices nn (1);
    std::vector<float> sq (1);
    for (const auto& p : scan)
      if (pcl::isXYZFinite (p))
      {
        pcl::PointXYZ q;
        q.getVector3fMap () = (pose * p.getVector3fMap ().cast<double> ()).cast<float> ();
        model.nearestKSearch (q, 1, nn, sq);
        d.push_back (std::sqrt (sq[0]));
      }
    std::nth_element (d.begin (), d.begin () + d.size () / 2, d.end ());
    return d[d.size () / 2];
  }

  std::string
  writeText (const std::string& name, const std::string& text)
  {
    const std::string path = ::testing::TempDir () + name;
    std::ofstream (path) << text;
    return path;
  }
}

// Known answer: q = 90 degrees about z maps (1, 0, 0) by R(q)^T, i.e. -90 degrees about z, to (0, -1, 0).
TEST (StanfordConf, ReadsTheStanfordConvention)
{
  const double s = std::sqrt (0.5);
  std::ostringstream text;
  text.precision (17);
  text << "camera -0.0172 -0.0936 -0.734  -0.0461723 0.970603 -0.235889 0.0124573\n"
       << "mesh bun000_cybcyl.ply 0 0 0 0 0 0 1\n\n# a comment\n"
       << "bmesh a.ply 1 2 3 0 0 " << s << " " << s << "\n"
       << "bmesh b.ply 0 0 0 0 0 0 1\n";
  const std::string path = writeText ("known.conf", text.str ());
  const auto entries = pcl::io::loadStanfordConf (path);
  ASSERT_EQ (entries.size (), 2u);
  EXPECT_EQ (entries[0].file, "a.ply");
  EXPECT_EQ (entries[1].file, "b.ply");
  const Eigen::Vector3d p = entries[0].pose () * Eigen::Vector3d (1, 0, 0);
  EXPECT_TRUE (p.isApprox (Eigen::Vector3d (1, 1, 3), 1e-15)) << p.transpose ();
  EXPECT_TRUE (entries[1].pose ().isApprox (Eigen::Affine3d::Identity (), 1e-15));
  std::remove (path.c_str ());
}

// Writing and reading back gives the same doubles, bit for bit, and a pose survives fromPose().
TEST (StanfordConf, RoundTripIsExact)
{
  std::mt19937 rng (11);
  std::uniform_real_distribution<double> u (-1.0, 1.0);
  std::vector<pcl::io::StanfordConfEntry> entries;
  for (int i = 0; i < 20; ++i)
  {
    const Eigen::Affine3d pose = Eigen::Translation3d (u (rng), u (rng), u (rng))
                               * Eigen::Quaterniond (u (rng), u (rng), u (rng), u (rng)).normalized ();
    entries.push_back (pcl::io::StanfordConfEntry::fromPose ("view_" + std::to_string (i) + ".ply", pose));
    EXPECT_TRUE (entries.back ().pose ().isApprox (pose, 1e-14));
  }
  const std::string path = ::testing::TempDir () + "roundtrip.conf";
  pcl::io::saveStanfordConf (path, entries);
  const auto back = pcl::io::loadStanfordConf (path);
  ASSERT_EQ (back.size (), entries.size ());
  for (std::size_t i = 0; i < back.size (); ++i)
  {
    EXPECT_EQ (back[i].file, entries[i].file);
    EXPECT_EQ (back[i].translation, entries[i].translation);
    EXPECT_EQ (back[i].quaternion.coeffs (), entries[i].quaternion.coeffs ());
  }
  std::remove (path.c_str ());
}

// pcl_tensor_model --keep-poses: a .conf names views by file name, wherever the files are.
TEST (StanfordConf, EntriesAreMatchedToFilesByName)
{
  std::vector<pcl::io::StanfordConfEntry> entries (3);
  entries[0].file = "b.ply";
  entries[1].file = "sub/a.ply";
  entries[2].file = "gone.ply";
  const std::vector<int> matched = pcl::io::confEntriesOfFiles (entries, {"/data/a.ply", "c.ply", "x/y/b.ply"});
  EXPECT_EQ (matched, (std::vector<int>{1, -1, 0}));
  EXPECT_THROW (pcl::io::confEntriesOfFiles (entries, {"one/a.ply", "two/a.ply"}), pcl::BadArgumentException)
      << "two views of one name: a pose could belong to either";
  EXPECT_EQ (pcl::io::confEntriesOfFiles (entries, {"one/c.ply", "two/c.ply"}), (std::vector<int>{-1, -1}))
      << "two views of a name no entry gives are not in question";
  entries[2].file = "other/b.ply";
  EXPECT_THROW (pcl::io::confEntriesOfFiles (entries, {"a.ply"}), pcl::BadArgumentException);
}

TEST (StanfordConf, FailsLoudlyOnBadFiles)
{
  EXPECT_THROW (pcl::io::loadStanfordConf ("/nonexistent/x.conf"), pcl::IOException);
  const std::string short_line = writeText ("short.conf", "bmesh a.ply 1 2 3 0 0 0\n");
  EXPECT_THROW (pcl::io::loadStanfordConf (short_line), pcl::IOException);
  const std::string unknown = writeText ("unknown.conf", "bmseh a.ply 1 2 3 0 0 0 1\n");
  EXPECT_THROW (pcl::io::loadStanfordConf (unknown), pcl::IOException);
  const std::string extra = writeText ("extra.conf", "bmesh a.ply 1 2 3 0 0 0 1 9\n");
  EXPECT_THROW (pcl::io::loadStanfordConf (extra), pcl::IOException);
  pcl::io::StanfordConfEntry spaced;
  spaced.file = "a b.ply";
  EXPECT_THROW (pcl::io::saveStanfordConf (::testing::TempDir () + "w.conf", {spaced}), pcl::IOException);
  EXPECT_THROW (pcl::io::saveStanfordConf ("/nonexistent/w.conf", {}), pcl::IOException);
}

// The real bun.conf lists the ten bunny scans; bun000 is the reference frame.
TEST (StanfordConf, ReadsBunConf)
{
  PCL_TENSOR_REQUIRE_SHARED_DATA (path, "stanford/bunny/bun.conf");
  const auto entries = pcl::io::loadStanfordConf (path);
  ASSERT_EQ (entries.size (), 10u);
  EXPECT_EQ (entries[0].file, "bun000.ply");
  EXPECT_TRUE (entries[0].pose ().isApprox (Eigen::Affine3d::Identity (), 1e-15));
  for (const auto& e : entries)
    EXPECT_NEAR (e.quaternion.norm (), 1.0, 1e-5) << e.file;
}

// The real poses align the real scans with the reconstruction: median nearest-vertex distance within
// 1.5 d_res (d_res of each scan's own triangulation). The transposed convention, R(q) p + t, must not
// pass for the scans that are turned by more than a few degrees: this is what the test tells apart.
TEST (StanfordConf, BunConfAlignsTheScansWithTheReconstruction)
{
  PCL_TENSOR_REQUIRE_SHARED_DATA (conf, "stanford/bunny/bun.conf");
  PCL_TENSOR_REQUIRE_SHARED_DATA (model_path, "stanford/bunny/bun_zipper.ply");
  const std::string dir = conf.substr (0, conf.find_last_of ('/') + 1);
  const auto model = pcl::io::loadScanMesh (model_path);
  pcl::PointCloud<pcl::PointXYZ>::Ptr vertices (new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : *model.cloud)
    vertices->push_back (pcl::PointXYZ (p.x, p.y, p.z));
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud (vertices);
  int wrong_convention_fails = 0;
  for (const auto& e : pcl::io::loadStanfordConf (conf))
  {
    const auto scan = pcl::io::loadRangeScan (dir + e.file);
    ASSERT_TRUE (scan.cloud->isOrganized ()) << e.file;
    pcl::RangeScanTriangulation triangulation;
    triangulation.setViewpoint (scan.viewpoint);
    pcl::ScanMesh mesh;
    triangulation.triangulate (*scan.cloud, mesh);
    const double d_res = pcl::meshResolution (mesh);
    const double median = medianDistance (*scan.cloud, e.pose (), tree);
    EXPECT_LE (median, 1.5 * d_res) << e.file << ": median " << median << " m, d_res " << d_res << " m";
    std::cout << "[   INFO   ] " << e.file << ": median " << median / d_res << " d_res (d_res " << d_res << " m)"
              << std::endl;
    Eigen::Affine3d transposed = e.pose ();
    transposed.linear () = e.quaternion.normalized ().toRotationMatrix ();
    wrong_convention_fails += medianDistance (*scan.cloud, transposed, tree) > 1.5 * d_res ? 1 : 0;
  }
  EXPECT_GE (wrong_convention_fails, 8);
}
