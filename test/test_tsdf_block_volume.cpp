/*
 * Known answers for the private sparse voxel volume and its marching cubes (src/surface/tsdf_block_volume.h):
 * the zero set of a sphere's exact signed distance, spread over many more blocks than one extraction
 * piece holds, is one closed surface on the sphere, the same on any number of threads.
 */
#include "surface/tsdf_block_volume.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

namespace
{
  using pcl::detail::kBlockSide;
  using pcl::detail::TsdfBlockVolume;

  constexpr double kVoxel = 0.01;
  constexpr double kRadius = 41.3 * kVoxel;  // off the voxel grid, so that no corner is exactly on the surface
  constexpr double kTruncation = 3.0 * kVoxel;

  /** A volume holding the signed distance of the sphere of kRadius about the origin (positive outside,
    * as a sensor outside sees it) in every block near its surface. */
  TsdfBlockVolume
  sphereVolume ()
  {
    TsdfBlockVolume volume (kVoxel, std::size_t (1) << 20);
    const int reach = static_cast<int> (std::ceil ((kRadius + kTruncation) / (kVoxel * kBlockSide))) + 1;
    for (int z = -reach; z <= reach; ++z)
      for (int y = -reach; y <= reach; ++y)
        for (int x = -reach; x <= reach; ++x)
        {
          // Blocks whose voxels (centre +- 3.5 voxels) come within the truncation of the surface, and a voxel more.
          const Eigen::Vector3d centre = (Eigen::Vector3d (x, y, z) * kBlockSide + Eigen::Vector3d::Constant (3.5)) * kVoxel;
          if (std::abs (centre.norm () - kRadius) <= std::sqrt (3.0) * 3.5 * kVoxel + kTruncation + kVoxel)
            volume.reserveBlock (Eigen::Vector3i (x, y, z));
        }
    volume.allocate ();
    for (std::size_t b = 0; b < volume.blockCount (); ++b)
    {
      const Eigen::Vector3i origin = volume.blockCoordinates (b) * kBlockSide;
      int i = 0;
      for (int z = 0; z < kBlockSide; ++z)
        for (int y = 0; y < kBlockSide; ++y)
          for (int x = 0; x < kBlockSide; ++x, ++i)
          {
            const double d = ((origin + Eigen::Vector3i (x, y, z)).cast<double> () * kVoxel).norm () - kRadius;
            if (std::abs (d) > kTruncation)
              continue;
            volume.block (b)[i].distance = static_cast<float> (d);
            volume.block (b)[i].weight = 1.0f;
          }
    }
    return volume;
  }
}

// Every edge of the sphere's mesh belongs to exactly two triangles and V - E + F = 2, so no vertex was
// left unwelded where one extraction piece meets another; every vertex lies on the sphere.
TEST (TsdfBlockVolume, SphereZeroSetIsOneClosedSurfaceAcrossPieces)
{
  const TsdfBlockVolume volume = sphereVolume ();
  ASSERT_GT (volume.blockCount (), 4u * 64u) << "the sphere must span several extraction pieces";
  std::vector<Eigen::Vector3f> vertices;
  std::vector<Eigen::Vector3i> triangles;
  pcl::detail::extractZeroSet (volume, vertices, triangles, 2);
  ASSERT_GT (triangles.size (), 10000u);

  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k)
      ++edges[{std::min (t[k], t[(k + 1) % 3]), std::max (t[k], t[(k + 1) % 3])}];
  for (const auto& e : edges)
    ASSERT_EQ (e.second, 2) << "edge " << e.first.first << "-" << e.first.second;
  const long euler = static_cast<long> (vertices.size ()) - static_cast<long> (edges.size ()) + static_cast<long> (triangles.size ());
  EXPECT_EQ (euler, 2);
  for (const auto& v : vertices)
    ASSERT_NEAR (v.cast<double> ().norm (), kRadius, 0.02 * kVoxel);
}

// Pieces are welded in block order: the mesh is the same, vertex for vertex, on 1, 2 and 5 threads.
TEST (TsdfBlockVolume, ZeroSetIsTheSameOnAnyNumberOfThreads)
{
  const TsdfBlockVolume volume = sphereVolume ();
  std::vector<Eigen::Vector3f> v1, vn;
  std::vector<Eigen::Vector3i> t1, tn;
  pcl::detail::extractZeroSet (volume, v1, t1, 1);
  for (const unsigned threads : {2u, 5u})
  {
    pcl::detail::extractZeroSet (volume, vn, tn, threads);
    ASSERT_EQ (vn.size (), v1.size ()) << threads << " threads";
    ASSERT_EQ (tn.size (), t1.size ()) << threads << " threads";
    for (std::size_t i = 0; i < v1.size (); ++i)
      ASSERT_EQ (vn[i], v1[i]) << threads << " threads, vertex " << i;
    for (std::size_t i = 0; i < t1.size (); ++i)
      ASSERT_EQ (tn[i], t1[i]) << threads << " threads, triangle " << i;
  }
}
