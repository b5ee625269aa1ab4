#include "test_utils.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/registration/global_verification.h>

namespace
{
  using pcl::registration::GlobalVerification;

  /** A flat plate of width x height on a regular grid of \a pitch, in the z = 0 plane. */
  pcl::PointCloud<pcl::PointNormal>
  plate (double width, double height, double pitch)
  {
    pcl::PointCloud<pcl::PointNormal> cloud;
    for (double x = 0.0; x <= width + 1e-9; x += pitch)
      for (double y = 0.0; y <= height + 1e-9; y += pitch)
      {
        pcl::PointNormal p;
        p.x = static_cast<float> (x);
        p.y = static_cast<float> (y);
        p.z = 0.0f;
        cloud.push_back (p);
      }
    return cloud;
  }

  Eigen::Affine3d
  shiftX (double dx)
  {
    return Eigen::Affine3d (Eigen::Translation3d (dx, 0.0, 0.0));
  }
}

TEST (GlobalVerification, ExcessIsTheGrowthOfTheCombinedExtents)
{
  // Two copies of a 0.2 x 0.1 plate, the second shifted along its length: the union stays symmetric,
  // so its principal axes are the plate's and its length grows by exactly the shift.
  const double d_res = 0.001;
  const auto view = plate (0.2, 0.1, 0.005);
  const pcl::ObjectDimensions dims = pcl::computeObjectDimensions<pcl::PointNormal> ({&view});
  EXPECT_NEAR (dims.D.x (), 0.2, 1e-6);
  EXPECT_NEAR (dims.D.y (), 0.1, 1e-6);

  GlobalVerification verification (dims, d_res);
  verification.addView (view, Eigen::Affine3d::Identity ());
  EXPECT_NEAR (verification.excess (view, Eigen::Affine3d::Identity ()), 0.0, 1e-3);
  EXPECT_NEAR (verification.excess (view, shiftX (0.003)), 3.0, 1e-3);
  EXPECT_TRUE (verification.accepts (view, shiftX (0.003)));
  EXPECT_NEAR (verification.excess (view, shiftX (0.010)), 10.0, 1e-3);
  EXPECT_FALSE (verification.accepts (view, shiftX (0.010))) << "10 d_res beyond D passed the 4 d_res tolerance";
}

TEST (GlobalVerification, EveryRegisteredViewCounts)
{
  // Each of three plates, placed end to end, passes with the first alone; the third, once the second
  // is registered, makes the whole 0.3 long against D = 0.2 (Section 4.2: all views so far).
  const double d_res = 0.001;
  const auto view = plate (0.1, 0.1, 0.005);
  pcl::ObjectDimensions dims;
  dims.D = Eigen::Vector3d (0.2, 0.1, 0.0);
  GlobalVerification verification (dims, d_res);
  verification.addView (view, Eigen::Affine3d::Identity ());
  EXPECT_TRUE (verification.accepts (view, shiftX (0.1)));
  verification.addView (view, shiftX (0.1));
  EXPECT_TRUE (verification.accepts (view, shiftX (0.05)));
  EXPECT_NEAR (verification.excess (view, shiftX (0.2)), 100.0, 0.5);
  EXPECT_FALSE (verification.accepts (view, shiftX (0.2)));
}

TEST (GlobalVerification, RefusesBadSettings)
{
  pcl::ObjectDimensions dims;
  EXPECT_THROW (GlobalVerification (dims, 0.0), pcl::BadArgumentException);
  pcl::registration::GlobalVerificationParams params;
  params.tolerance = -1.0;
  EXPECT_THROW (GlobalVerification (dims, 0.001, params), pcl::BadArgumentException);
}
