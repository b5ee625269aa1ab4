/*
 * pcl_tensor: tests of the exact point-to-mesh distance.
 */
#include "test_utils.h"

#include <pcl/common/point_mesh_distance.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/simulation/example_object.h>

#include <random>

TEST (PointMeshDistance, TriangleRegions)
{
  const Eigen::Vector3d a (0, 0, 0), b (1, 0, 0), c (0, 1, 0);
  EXPECT_NEAR (pcl::pointTriangleDistance ({0.2, 0.2, 0.5}, a, b, c), 0.5, 1e-15);       // face
  EXPECT_NEAR (pcl::pointTriangleDistance ({-1, -1, 0}, a, b, c), std::sqrt (2.0), 1e-15);  // vertex a
  EXPECT_NEAR (pcl::pointTriangleDistance ({2, 0, 1}, a, b, c), std::sqrt (2.0), 1e-15);    // vertex b
  EXPECT_NEAR (pcl::pointTriangleDistance ({0.5, -2, 0}, a, b, c), 2.0, 1e-15);             // edge ab
  EXPECT_NEAR (pcl::pointTriangleDistance ({1, 1, 0}, a, b, c), std::sqrt (0.5), 1e-15);    // edge bc
}

// Against brute force over every triangle, for points near and far from the surface.
TEST (PointMeshDistance, MatchesBruteForce)
{
  pcl::ExampleObjectParams params;
  params.subdivisions = 3;
  const auto mesh = pcl::makeExampleObject (params);
  pcl::PointMeshDistance distance;
  distance.setMesh (mesh);
  std::mt19937 rng (3);
  std::uniform_real_distribution<double> u (-0.15, 0.15);
  for (int k = 0; k < 200; ++k)
  {
    const Eigen::Vector3d p (u (rng), u (rng), u (rng));
    double brute = std::numeric_limits<double>::max ();
    for (const auto& t : mesh.polygons)
      brute = std::min (brute, pcl::pointTriangleDistance (p, (*mesh.cloud)[t.vertices[0]].getVector3fMap ().cast<double> (),
                                                           (*mesh.cloud)[t.vertices[1]].getVector3fMap ().cast<double> (),
                                                           (*mesh.cloud)[t.vertices[2]].getVector3fMap ().cast<double> ()));
    EXPECT_DOUBLE_EQ (distance.distance (p), brute) << k;
  }
}

TEST (PointMeshDistance, RejectsMissingMesh)
{
  pcl::PointMeshDistance distance;
  EXPECT_THROW (distance.distance (Eigen::Vector3d::Zero ()), pcl::InvalidScanException);
  EXPECT_THROW (distance.setMesh (pcl::ScanMesh ()), pcl::InvalidScanException);
}
