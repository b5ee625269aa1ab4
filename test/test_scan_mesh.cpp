#include <pcl/common/scan_mesh.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/conversions.h>

#include <gtest/gtest.h>

namespace
{
  /** The unit square as two triangles: edges 1, 1, 1, 1 and one diagonal of sqrt(2). */
  pcl::ScanMesh
  unitSquare ()
  {
    pcl::ScanMesh mesh;
    for (const auto& p : {pcl::PointXYZ (0, 0, 0), pcl::PointXYZ (1, 0, 0), pcl::PointXYZ (1, 1, 0), pcl::PointXYZ (0, 1, 0)})
    {
      pcl::PointNormal q;
      q.x = p.x; q.y = p.y; q.z = p.z;
      q.normal_x = q.normal_y = 0.0f; q.normal_z = 1.0f;
      mesh.cloud->push_back (q);
    }
    pcl::Vertices a, b;
    a.vertices = {0, 1, 2};
    b.vertices = {0, 2, 3};
    mesh.polygons = {a, b};
    return mesh;
  }
}

TEST (ScanMesh, ResolutionIsTheMeanOfDistinctEdges)
{
  EXPECT_NEAR (pcl::meshResolution (unitSquare ()), (4.0 + std::sqrt (2.0)) / 5.0, 1e-12);
  EXPECT_EQ (pcl::meshResolution (pcl::ScanMesh ()), 0.0);
}

TEST (ScanMesh, AreaOfTheUnitSquare)
{
  EXPECT_NEAR (pcl::meshArea (unitSquare ()), 1.0, 1e-12);
}

TEST (ScanMesh, PolygonMeshRoundTripKeepsVerticesNormalsAndFaces)
{
  pcl::PolygonMesh polygon_mesh;
  pcl::toPolygonMesh (unitSquare (), polygon_mesh);
  pcl::ScanMesh back;
  pcl::fromPolygonMesh (polygon_mesh, back);
  ASSERT_EQ (back.cloud->size (), 4u);
  EXPECT_EQ (back.polygons.size (), 2u);
  EXPECT_EQ ((*back.cloud)[2].getVector3fMap (), Eigen::Vector3f (1, 1, 0));
  EXPECT_EQ ((*back.cloud)[2].normal_z, 1.0f);
}

TEST (ScanMesh, QuadsAreFannedAndBadIndicesThrow)
{
  pcl::PolygonMesh polygon_mesh;
  pcl::toPolygonMesh (unitSquare (), polygon_mesh);
  pcl::Vertices quad;
  quad.vertices = {0, 1, 2, 3};
  polygon_mesh.polygons = {quad};
  pcl::ScanMesh back;
  pcl::fromPolygonMesh (polygon_mesh, back);
  EXPECT_EQ (back.polygons.size (), 2u);
  EXPECT_NEAR (pcl::meshArea (back), 1.0, 1e-12);

  polygon_mesh.polygons[0].vertices = {0, 1, 7};
  EXPECT_THROW (pcl::fromPolygonMesh (polygon_mesh, back), pcl::InvalidScanException);
  pcl::PolygonMesh no_vertices;
  no_vertices.polygons = {quad};
  EXPECT_THROW (pcl::fromPolygonMesh (no_vertices, back), pcl::InvalidScanException);
}
