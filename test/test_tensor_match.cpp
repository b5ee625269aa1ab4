#include "test_utils.h"

#include <pcl/registration/tensor_match.h>

#include <gtest/gtest.h>

#include <random>

namespace
{
  pcl::TensorDescriptor
  sparseTensor (const std::vector<std::uint16_t>& bins, const std::vector<float>& areas)
  {
    pcl::TensorDescriptor t;
    t.grid_size = 10;
    t.bin_index = bins;
    t.bin_area = areas;
    return t;
  }

  /** A tensor with only a frame (rows x, y, z) and an origin. */
  pcl::TensorDescriptor
  framedTensor (const Eigen::Matrix3f& axes_as_rows, const Eigen::Vector3f& origin)
  {
    pcl::TensorDescriptor t;
    t.getVector3fMap () = origin;
    Eigen::Map<Eigen::Matrix<float, 3, 3, Eigen::RowMajor>> (t.rf) = axes_as_rows;
    return t;
  }
}

TEST (TensorComparator, Eq5And6KnownAnswers)
{
  pcl::registration::TensorComparator comparator;
  pcl::registration::TensorMatch m;
  // Identical: R_O = 1, C_c = 1.
  const auto a = sparseTensor ({3, 10, 200, 999}, {1.0f, 2.0f, 3.0f, 4.0f});
  comparator.setScene (a);
  comparator.compare (a, m);
  EXPECT_FLOAT_EQ (m.overlap_ratio, 1.0f);
  EXPECT_NEAR (m.correlation, 1.0f, 1e-6f);
  EXPECT_EQ (m.n_q, 4);
  // Proportional on 3 shared bins of 4 + 5 distinct: R_O = 3 / (4 + 5 - 3) = 0.5, C_c = 1.
  const auto b = sparseTensor ({3, 10, 200, 500, 501}, {2.0f, 4.0f, 6.0f, 9.0f, 9.0f});
  comparator.compare (b, m);
  EXPECT_FLOAT_EQ (m.overlap_ratio, 0.5f);
  EXPECT_NEAR (m.correlation, 1.0f, 1e-6f);
  // Reversed order on the overlap: C_c = -1.
  const auto c = sparseTensor ({3, 10, 200}, {3.0f, 2.0f, 1.0f});
  comparator.compare (c, m);
  EXPECT_NEAR (m.correlation, -1.0f, 1e-6f);
  // Disjoint: R_O = 0 and no correlation.
  const auto d = sparseTensor ({0, 1}, {1.0f, 1.0f});
  comparator.compare (d, m);
  EXPECT_EQ (m.n_q, 0);
  EXPECT_EQ (m.overlap_ratio, 0.0f);
  EXPECT_EQ (m.correlation, 0.0f);
  // A new scene replaces the old one completely.
  comparator.setScene (d);
  comparator.compare (a, m);
  EXPECT_EQ (m.n_q, 0);
}

TEST (TensorComparator, CorrelationMatchesAnIndependentComputation)
{
  std::mt19937 rng (5);
  std::uniform_real_distribution<float> u (0.0f, 1.0f);
  std::vector<std::uint16_t> bins;
  std::vector<float> p, q;
  for (std::uint16_t k = 0; k < 1000; k += 7)
  {
    bins.push_back (k);
    p.push_back (u (rng));
    q.push_back (0.5f * p.back () + u (rng));
  }
  pcl::registration::TensorComparator comparator;
  comparator.setScene (sparseTensor (bins, q));
  pcl::registration::TensorMatch m;
  comparator.compare (sparseTensor (bins, p), m);
  const double n = static_cast<double> (bins.size ());
  double mp = 0, mq = 0;
  for (std::size_t i = 0; i < p.size (); ++i)
  {
    mp += p[i] / n;
    mq += q[i] / n;
  }
  double cov = 0, vp = 0, vq = 0;
  for (std::size_t i = 0; i < p.size (); ++i)
  {
    cov += (p[i] - mp) * (q[i] - mq);
    vp += (p[i] - mp) * (p[i] - mp);
    vq += (q[i] - mq) * (q[i] - mq);
  }
  EXPECT_NEAR (m.correlation, cov / std::sqrt (vp * vq), 1e-5);
}

TEST (TransformFromTensorPair, RecoversAKnownRigidMotion)
{
  // Eq. 7-8: a frame seen in the scene and the same frame seen in the model after a motion T.
  std::mt19937 rng (7);
  for (int trial = 0; trial < 20; ++trial)
  {
    // Columns of frame are the axes; rows go into the descriptor.
    const Eigen::Matrix3f frame = pcl_tensor_test::randomRigidTransform (rng, 0.0).linear ().cast<float> ();
    const Eigen::Vector3f origin (0.1f * trial, -0.02f, 0.3f);
    const Eigen::Affine3f t (pcl_tensor_test::randomRigidTransform (rng, 0.5).matrix ().cast<float> ());
    const auto scene = framedTensor (frame.transpose (), origin);
    const auto model = framedTensor ((t.linear () * frame).transpose (), t * origin);
    const Eigen::Matrix4f estimate = pcl::registration::transformFromTensorPair (model, scene);
    EXPECT_TRUE (estimate.isApprox (t.matrix (), 1e-5f)) << "trial " << trial << "\n" << estimate << "\n" << t.matrix ();
  }
}

TEST (TransformFromTensorMatch, EqualsThePairInTheOrderThatMatched)
{
  std::mt19937 rng (5);
  pcl::PointCloud<pcl::TensorDescriptor> model, scene;
  for (int k = 0; k < 4; ++k)
  {
    const Eigen::Matrix3f frame = pcl_tensor_test::randomRigidTransform (rng, 0.0).linear ().cast<float> ();
    model.push_back (framedTensor (frame.transpose (), Eigen::Vector3f (0.1f * k, 0.2f, -0.1f)));
    const Eigen::Matrix3f other = pcl_tensor_test::randomRigidTransform (rng, 0.0).linear ().cast<float> ();
    scene.push_back (framedTensor (other.transpose (), Eigen::Vector3f (-0.3f, 0.05f * k, 0.4f)));
  }
  for (const bool flipped : {false, true})
  {
    pcl::registration::TensorMatch match;
    match.model = 2;
    match.scene = 1;
    match.scene_flipped = flipped;
    const Eigen::Matrix4f expected =
        pcl::registration::transformFromTensorPair (model[2], flipped ? pcl::flipPairOrder (scene[1]) : scene[1]);
    EXPECT_TRUE (pcl::registration::transformFromTensorMatch (match, model, scene).isApprox (expected, 1e-6f)) << "flipped " << flipped;
  }
}

TEST (TensorBinSet, SharedBinsAndOverlapEqualTheComparators)
{
  std::mt19937 rng (11);
  for (const int grid : {10, 15})
    for (int trial = 0; trial < 50; ++trial)
    {
      auto random_tensor = [&] () {
        std::bernoulli_distribution occupied (0.05 + 0.01 * (trial % 20));
        pcl::TensorDescriptor t;
        t.grid_size = grid;
        for (int k = 0; k < grid * grid * grid; ++k)
          if (occupied (rng))
          {
            t.bin_index.push_back (static_cast<std::uint16_t> (k));
            t.bin_area.push_back (1.0f + static_cast<float> (k % 7));
          }
        return t;
      };
      const auto scene = random_tensor (), model = random_tensor ();
      pcl::registration::TensorComparator comparator;
      comparator.setScene (scene);
      pcl::registration::TensorMatch m;
      comparator.compare (model, m);
      const pcl::registration::TensorBinSet s (scene), t (model);
      ASSERT_EQ (s.countShared (t), m.n_q);
      EXPECT_EQ (t.size (), static_cast<int> (model.bin_index.size ()));
      // Bit-equal R_O: the matcher's pre-check must never drop a match the comparator would keep.
      EXPECT_EQ (pcl::registration::overlapRatio (s.countShared (t), model.bin_index.size (), scene.bin_index.size ()),
                 m.overlap_ratio);
    }
}
