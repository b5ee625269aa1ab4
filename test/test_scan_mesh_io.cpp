#include <pcl/common/tensor_exceptions.h>
#include <pcl/conversions.h>
#include <pcl/io/ply_io.h>
#include <pcl/io/scan_mesh_io.h>

#include <gtest/gtest.h>

#include <random>

namespace
{
  /** A mesh of random vertices (fixed seed), with normals and curvature set, and random triangles. */
  pcl::ScanMesh
  randomMesh (std::size_t vertices, std::size_t triangles)
  {
    std::mt19937 rng (7);
    std::uniform_real_distribution<float> u (-2.0f, 2.0f);
    std::uniform_int_distribution<int> pick (0, static_cast<int> (vertices) - 1);
    pcl::ScanMesh mesh;
    for (std::size_t i = 0; i < vertices; ++i)
    {
      pcl::PointNormal p;
      p.x = u (rng); p.y = u (rng); p.z = u (rng);
      p.normal_x = u (rng); p.normal_y = u (rng); p.normal_z = u (rng);
      p.curvature = u (rng);
      mesh.cloud->push_back (p);
    }
    for (std::size_t t = 0; t < triangles; ++t)
    {
      pcl::Vertices tri;
      tri.vertices = {static_cast<pcl::index_t> (pick (rng)), static_cast<pcl::index_t> (pick (rng)),
                      static_cast<pcl::index_t> (pick (rng))};
      mesh.polygons.push_back (tri);
    }
    return mesh;
  }

  void
  expectSameMesh (const pcl::ScanMesh& a, const pcl::ScanMesh& b)
  {
    ASSERT_EQ (a.cloud->size (), b.cloud->size ());
    for (std::size_t i = 0; i < a.cloud->size (); ++i)
    {
      const auto& p = (*a.cloud)[i];
      const auto& q = (*b.cloud)[i];
      // Bit for bit: the floats are written as they are.
      EXPECT_EQ (p.getVector3fMap (), q.getVector3fMap ()) << i;
      EXPECT_EQ (p.getNormalVector3fMap (), q.getNormalVector3fMap ()) << i;
      EXPECT_EQ (p.curvature, q.curvature) << i;
    }
    ASSERT_EQ (a.polygons.size (), b.polygons.size ());
    for (std::size_t t = 0; t < a.polygons.size (); ++t)
      EXPECT_EQ (a.polygons[t].vertices, b.polygons[t].vertices) << t;
  }
}

TEST (ScanMeshIo, PclReadsWhatSaveScanMeshWrites)
{
  const pcl::ScanMesh mesh = randomMesh (500, 900);
  const std::string path = ::testing::TempDir () + "scan_mesh_io_pcl.ply";
  pcl::io::saveScanMesh (path, mesh);
  pcl::PolygonMesh read;
  ASSERT_GE (pcl::io::loadPLYFile (path, read), 0);
  pcl::ScanMesh back;
  pcl::fromPolygonMesh (read, back);
  expectSameMesh (mesh, back);
}

TEST (ScanMeshIo, SavedMeshIsTheOneSavePlyFileBinaryWrites)
{
  const pcl::ScanMesh mesh = randomMesh (300, 400);
  const std::string ours = ::testing::TempDir () + "scan_mesh_io_ours.ply";
  const std::string theirs = ::testing::TempDir () + "scan_mesh_io_pcl_writer.ply";
  pcl::io::saveScanMesh (ours, mesh);
  pcl::PolygonMesh polygon_mesh;
  pcl::toPolygonMesh (mesh, polygon_mesh);
  ASSERT_GE (pcl::io::savePLYFileBinary (theirs, polygon_mesh), 0);
  expectSameMesh (pcl::io::loadScanMesh (ours), pcl::io::loadScanMesh (theirs));
}

TEST (ScanMeshIo, EmptyMeshAndUnwritablePath)
{
  const std::string path = ::testing::TempDir () + "scan_mesh_io_empty.ply";
  pcl::io::saveScanMesh (path, pcl::ScanMesh ());
  pcl::PolygonMesh read;
  ASSERT_GE (pcl::io::loadPLYFile (path, read), 0);
  EXPECT_EQ (read.cloud.width * read.cloud.height, 0u);
  EXPECT_TRUE (read.polygons.empty ());
  EXPECT_THROW (pcl::io::saveScanMesh ("/nonexistent-dir/x.ply", randomMesh (3, 1)), pcl::IOException);
}
