#include <pcl/common/object_dimensions.h>
#include <pcl/simulation/example_object.h>

#include <gtest/gtest.h>

#include <map>

TEST (ExampleObject, IsAClosedManifoldWithOutwardNormals)
{
  pcl::ExampleObjectParams params;
  params.subdivisions = 4;
  const pcl::ScanMesh mesh = pcl::makeExampleObject (params);
  EXPECT_EQ (mesh.polygons.size (), 20u * 256u);
  std::map<std::pair<int, int>, int> edge_uses;
  for (const auto& poly : mesh.polygons)
    for (int e = 0; e < 3; ++e)
    {
      const int a = poly.vertices[e], b = poly.vertices[(e + 1) % 3];
      ++edge_uses[{std::min (a, b), std::max (a, b)}];
    }
  for (const auto& [edge, uses] : edge_uses)
    ASSERT_EQ (uses, 2) << "edge " << edge.first << "-" << edge.second;

  // Outward: the divergence theorem gives a positive volume for outward-wound faces.
  double volume = 0.0;
  for (const auto& poly : mesh.polygons)
  {
    const Eigen::Vector3d a = (*mesh.cloud)[poly.vertices[0]].getVector3fMap ().cast<double> ();
    const Eigen::Vector3d b = (*mesh.cloud)[poly.vertices[1]].getVector3fMap ().cast<double> ();
    const Eigen::Vector3d c = (*mesh.cloud)[poly.vertices[2]].getVector3fMap ().cast<double> ();
    volume += a.dot (b.cross (c)) / 6.0;
  }
  EXPECT_GT (volume, 0.0);
  std::size_t outward = 0;
  for (const auto& p : *mesh.cloud)
    outward += p.getNormalVector3fMap ().dot (p.getVector3fMap ()) > 0.0f;
  EXPECT_GT (outward, mesh.cloud->size () * 9 / 10);
}

TEST (ExampleObject, IsDeterministicPerSeedAndAsymmetric)
{
  pcl::ExampleObjectParams params;
  params.subdivisions = 3;
  const pcl::ScanMesh a = pcl::makeExampleObject (params), b = pcl::makeExampleObject (params);
  params.seed += 1;
  const pcl::ScanMesh c = pcl::makeExampleObject (params);
  ASSERT_EQ (a.cloud->size (), c.cloud->size ());
  double same = 0.0, different = 0.0;
  for (std::size_t i = 0; i < a.cloud->size (); ++i)
  {
    same += ((*a.cloud)[i].getVector3fMap () - (*b.cloud)[i].getVector3fMap ()).norm ();
    different += ((*a.cloud)[i].getVector3fMap () - (*c.cloud)[i].getVector3fMap ()).norm ();
  }
  EXPECT_EQ (same, 0.0);
  EXPECT_GT (different, 0.0);

  // No two principal extents alike: no rotational symmetry about a principal axis.
  const Eigen::Vector3d d = pcl::principalExtents (*a.cloud);
  EXPECT_GT (d[0] / d[1], 1.05);
  EXPECT_GT (d[1] / d[2], 1.05);
  EXPECT_NEAR (d[0], params.size, 0.5 * params.size);
}
