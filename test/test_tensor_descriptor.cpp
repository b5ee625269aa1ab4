/*
 * Tests of the pcl::TensorDescriptor point type: registration, copies, memory, kd-tree use.
 */
#include "test_utils.h"

#include <pcl/common/io.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/features/tensor_descriptor.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/kdtree/impl/kdtree_flann.hpp>  // KdTreeFLANN over a point type of this project
#include <pcl/type_traits.h>

#include <limits>
#include <set>
#include <sstream>

namespace
{
  /** A random sparse tensor: distinct sorted bin indices, positive areas. */
  pcl::TensorDescriptor
  randomTensor (std::mt19937& rng, int n, int non_zero)
  {
    pcl::TensorDescriptor t;
    std::uniform_real_distribution<float> u (0.f, 1.f);
    std::uniform_int_distribution<int> bin (0, n * n * n - 1);
    std::set<int> bins;
    while (static_cast<int> (bins.size ()) < non_zero)
      bins.insert (bin (rng));
    for (const int b : bins)
    {
      t.bin_index.push_back (static_cast<std::uint16_t> (b));
      t.bin_area.push_back (u (rng) + 0.01f);
    }
    t.grid_size = n;
    t.bin_size = 0.005f;
    t.x = u (rng);
    t.y = u (rng);
    t.z = u (rng);
    t.theta_d = 180.f * u (rng);
    t.vertex_a = 3;
    t.vertex_b = 8;
    const float rf[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    std::copy (rf, rf + 9, t.rf);
    return t;
  }
}

TEST (TensorDescriptor, RegisteredFieldsAreTheFixedOnes)
{
  std::vector<pcl::PCLPointField> fields;
  pcl::getFields<pcl::TensorDescriptor> (fields);
  std::vector<std::string> names;
  for (const auto& f : fields)
    names.push_back (f.name);
  const std::vector<std::string> expected {"x", "y", "z", "rf", "theta_d", "bin_size", "vertex_a", "vertex_b",
                                           "grid_size", "order_ambiguous"};
  EXPECT_EQ (names, expected);
  EXPECT_EQ (pcl::TensorDescriptor::descriptorSize (), 1000);
  EXPECT_EQ (alignof (pcl::TensorDescriptor), 16u);
  EXPECT_EQ (pcl::TENSOR_MAX_GRID_SIZE * pcl::TENSOR_MAX_GRID_SIZE * pcl::TENSOR_MAX_GRID_SIZE <= 65535, true);
}

TEST (TensorDescriptor, CloudCopiesKeepTheBins)
{
  std::mt19937 rng (7);
  pcl::PointCloud<pcl::TensorDescriptor> cloud;
  for (int k = 0; k < 20; ++k)
    cloud.push_back (randomTensor (rng, 10, 5 + k));
  const pcl::PointCloud<pcl::TensorDescriptor> copy = cloud;                     // copy constructor
  pcl::PointCloud<pcl::TensorDescriptor>::Ptr shared = cloud.makeShared ();      // shared copy
  pcl::PointCloud<pcl::TensorDescriptor> subset;
  pcl::copyPointCloud (cloud, pcl::Indices {3, 11, 19}, subset);                 // indexed copy
  pcl::PointCloud<pcl::TensorDescriptor> appended = cloud;
  appended += cloud;                                                             // concatenation
  cloud[0].bin_area[0] = -1.f;  // the copies are deep
  for (std::size_t k = 0; k < copy.size (); ++k)
  {
    const auto& expected = k == 0 ? copy[0] : cloud[k];
    EXPECT_EQ (copy[k].bin_index, expected.bin_index);
    EXPECT_EQ (copy[k].bin_area, expected.bin_area);
    EXPECT_EQ ((*shared)[k].bin_index, expected.bin_index);
    EXPECT_EQ (appended[k + copy.size ()].bin_area, expected.bin_area);
  }
  EXPECT_GT (copy[0].bin_area[0], 0.f);
  ASSERT_EQ (subset.size (), 3u);
  EXPECT_EQ (subset[1].bin_index, cloud[11].bin_index);
  EXPECT_EQ (subset[2].bin_area, cloud[19].bin_area);
  EXPECT_EQ (subset[2].theta_d, cloud[19].theta_d);
}

TEST (TensorDescriptor, MemoryUsageSparseAgainstDense)
{
  std::mt19937 rng (8);
  pcl::PointCloud<pcl::TensorDescriptor> cloud;
  cloud.push_back (randomTensor (rng, 10, 100));
  cloud.push_back (randomTensor (rng, 15, 50));
  const pcl::TensorMemoryUsage m = pcl::computeTensorMemoryUsage (cloud);
  EXPECT_EQ (m.tensors, 2u);
  EXPECT_EQ (m.non_zero_bins, 150u);
  EXPECT_EQ (m.sparse_bin_bytes, 150u * 6u);
  EXPECT_EQ (m.dense_bin_bytes, (1000u + 3375u) * 4u);
  EXPECT_EQ (m.sparse_bytes, 2 * sizeof (pcl::TensorDescriptor) + 900u);
  EXPECT_GT (m.savedFraction (), 0.0);
}

TEST (TensorDescriptor, FlipPairOrderIsAnExactInvolution)
{
  std::mt19937 rng (9);
  for (const int n : {10, 15})
  {
    const pcl::TensorDescriptor t = randomTensor (rng, n, 40);
    const pcl::TensorDescriptor f = pcl::flipPairOrder (t);
    EXPECT_EQ (f.vertex_a, t.vertex_b);
    EXPECT_EQ (f.rf[0], -t.rf[0]);
    EXPECT_EQ (f.rf[4], -t.rf[4]);
    EXPECT_EQ (f.rf[8], t.rf[8]);
    EXPECT_TRUE (std::is_sorted (f.bin_index.begin (), f.bin_index.end ()));
    std::vector<float> dt, df;
    pcl::toDenseTensor (t, dt);
    pcl::toDenseTensor (f, df);
    for (int ix = 0; ix < n; ++ix)
      for (int iy = 0; iy < n; ++iy)
        for (int iz = 0; iz < n; ++iz)
          EXPECT_EQ (df[((n - 1 - ix) * n + (n - 1 - iy)) * n + iz], dt[(ix * n + iy) * n + iz]);
    const pcl::TensorDescriptor back = pcl::flipPairOrder (f);
    EXPECT_EQ (back.bin_index, t.bin_index);
    EXPECT_EQ (back.bin_area, t.bin_area);
  }
}

TEST (TensorDescriptor, KdTreeFlannWorksWithTheDenseRepresentation)
{
  std::mt19937 rng (10);
  pcl::PointCloud<pcl::TensorDescriptor>::Ptr cloud (new pcl::PointCloud<pcl::TensorDescriptor>);
  for (int k = 0; k < 50; ++k)
    cloud->push_back (randomTensor (rng, 10, 60));
  pcl::KdTreeFLANN<pcl::TensorDescriptor> tree;
  tree.setInputCloud (cloud);
  pcl::Indices nn;
  std::vector<float> dist;
  for (int k = 0; k < 50; k += 7)
  {
    ASSERT_EQ (tree.nearestKSearch ((*cloud)[k], 1, nn, dist), 1);
    EXPECT_EQ (nn[0], k);
    EXPECT_NEAR (dist[0], 0.f, 1e-6f);
  }
  // A 15^3 tensor needs a 15^3 representation; the default one refuses it rather than truncating.
  pcl::PointCloud<pcl::TensorDescriptor>::Ptr big (new pcl::PointCloud<pcl::TensorDescriptor>);
  for (int k = 0; k < 10; ++k)
    big->push_back (randomTensor (rng, 15, 60));
  pcl::KdTreeFLANN<pcl::TensorDescriptor> tree15;
  EXPECT_THROW (tree15.setInputCloud (big), pcl::BadArgumentException);
  tree15.setPointRepresentation (pcl::TensorPointRepresentation::ConstPtr (new pcl::TensorPointRepresentation (15)));
  tree15.setInputCloud (big);
  ASSERT_EQ (tree15.nearestKSearch ((*big)[4], 1, nn, dist), 1);
  EXPECT_EQ (nn[0], 4);
  pcl::TensorDescriptor with_nan = (*cloud)[0];
  ASSERT_FALSE (with_nan.bin_area.empty ());
  EXPECT_TRUE (pcl::TensorPointRepresentation ().isValid (with_nan));
  with_nan.bin_area.back () = std::numeric_limits<float>::quiet_NaN ();
  EXPECT_FALSE (pcl::TensorPointRepresentation ().isValid (with_nan)) << "a NaN bin makes the tensor invalid";
  EXPECT_THROW (pcl::TensorPointRepresentation (0), pcl::BadArgumentException);
  EXPECT_THROW (pcl::TensorPointRepresentation (41), pcl::BadArgumentException);
}

TEST (TensorDescriptor, Prints)
{
  std::mt19937 rng (11);
  std::ostringstream s;
  s << randomTensor (rng, 10, 3);
  EXPECT_NE (s.str ().find ("non-zero bins: 3"), std::string::npos);
}
