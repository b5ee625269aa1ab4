/*
 * Tests of pcl::TensorThetaIndex, the 1D theta_d index table of Section 2.
 */
#include "test_utils.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/features/tensor_index.h>

#include <algorithm>
#include <cmath>

TEST (TensorThetaIndex, CandidatesAreTheThreeBinsAroundTheta)
{
  std::mt19937 rng (13);
  std::uniform_real_distribution<float> theta (0.f, 180.f);
  pcl::PointCloud<pcl::TensorDescriptor> tensors;
  for (int k = 0; k < 500; ++k)
  {
    pcl::TensorDescriptor t;
    t.theta_d = theta (rng);
    tensors.push_back (t);
  }
  tensors[0].theta_d = 0.f;
  tensors[1].theta_d = 180.f;
  tensors[2].theta_d = 5.f;
  for (const double width : {5.0, 7.0})
  {
    pcl::TensorThetaIndex index (width);
    index.build (tensors);
    EXPECT_EQ (index.getNumBins (), static_cast<int> (std::ceil (180.0 / width)));
    EXPECT_EQ (index.size (), tensors.size ());
    for (const double q : {0.0, 2.5, 5.0, 44.9, 90.0, 177.0, 180.0})
    {
      const int b = index.binOf (q);
      std::vector<int> expected;
      for (int k = 0; k < static_cast<int> (tensors.size ()); ++k)
        if (std::abs (index.binOf (tensors[k].theta_d) - b) <= 1)
          expected.push_back (k);
      const auto range = index.candidates (q);
      std::vector<int> got (range.begin (), range.end ());
      std::sort (got.begin (), got.end ());
      EXPECT_EQ (got, expected) << "theta_d = " << q << ", width " << width;
      // Every tensor within +- width of the query is a candidate (Section 4).
      for (int k = 0; k < static_cast<int> (tensors.size ()); ++k)
      {
        const bool within = std::abs (tensors[k].theta_d - q) <= width;
        EXPECT_TRUE (!within || std::binary_search (got.begin (), got.end (), k)) << k;
      }
    }
    EXPECT_EQ (index.binOf (180.0), index.getNumBins () - 1);
    EXPECT_EQ (index.binOf (5.0), width == 5.0 ? 1 : 0);
  }
}

TEST (TensorThetaIndex, RejectsBadInput)
{
  EXPECT_THROW (pcl::TensorThetaIndex (0.0), pcl::BadArgumentException);
  EXPECT_THROW (pcl::TensorThetaIndex (-5.0), pcl::BadArgumentException);
  pcl::TensorThetaIndex index;
  EXPECT_EQ (index.getBinWidth (), 5.0);
  EXPECT_TRUE (index.candidates (30.0).empty ());
  pcl::PointCloud<pcl::TensorDescriptor> tensors;
  tensors.push_back (pcl::TensorDescriptor ());
  tensors[0].theta_d = std::nanf ("");
  EXPECT_THROW (index.build (tensors), pcl::BadArgumentException);
  tensors[0].theta_d = 181.f;
  EXPECT_THROW (index.build (tensors), pcl::BadArgumentException);
}
