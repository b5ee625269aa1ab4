/*
 * pcl_tensor: known-answer tests of the error measures of Section 7 (Eqs. 10-12 and 14).
 */
#include "test_utils.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/registration/registration_error.h>

namespace
{
  pcl::PointCloud<pcl::PointXYZ>
  grid (int n, double spacing)
  {
    pcl::PointCloud<pcl::PointXYZ> c;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        c.push_back (pcl::PointXYZ (static_cast<float> (i * spacing), static_cast<float> (j * spacing), 0.0f));
    return c;
  }
}

TEST (RegistrationError, OneDegreeRotationGivesOneDegree)
{
  const Eigen::Matrix3d gt (Eigen::AngleAxisd (0.7, Eigen::Vector3d (1, 2, 3).normalized ()));
  const Eigen::Matrix3d est = Eigen::AngleAxisd (M_PI / 180.0, Eigen::Vector3d (-2, 0, 1).normalized ()) * gt;
  EXPECT_NEAR (pcl::rotationErrorDeg (est, gt), 1.0, 1e-6);
  EXPECT_NEAR (pcl::rotationErrorDeg (gt, gt), 0.0, 1e-6);
  // Rounding could push (trace - 1) / 2 past 1 for equal rotations; the answer stays a number.
  EXPECT_FALSE (std::isnan (pcl::rotationErrorDeg (Eigen::Matrix3d::Identity () * (1.0 + 1e-15), Eigen::Matrix3d::Identity ())));
  const Eigen::Matrix3d half_turn (Eigen::AngleAxisd (M_PI, Eigen::Vector3d::UnitZ ()));
  EXPECT_NEAR (pcl::rotationErrorDeg (half_turn, Eigen::Matrix3d::Identity ()), 180.0, 1e-6);
}

// A float pose (as every transform here is) keeps an angle of 0.001 deg: the trace alone, rounded to
// float, would put it anywhere in 0-0.03 deg.
TEST (RegistrationError, TinyRotationOfAFloatPoseIsMeasured)
{
  const Eigen::Matrix3d gt (Eigen::AngleAxisd (0.7, Eigen::Vector3d (1, 2, 3).normalized ()));
  const Eigen::Matrix3f est = (Eigen::AngleAxisd (1e-3 * M_PI / 180.0, Eigen::Vector3d (-2, 0, 1).normalized ()) * gt).cast<float> ();
  EXPECT_NEAR (pcl::rotationErrorDeg (est.cast<double> (), gt), 1e-3, 1e-4);
}

TEST (RegistrationError, ThreeResolutionsOfTranslationGiveThree)
{
  const double d_res = 0.0015;
  const Eigen::Vector3d gt (0.1, -0.2, 0.3);
  const Eigen::Vector3d est = gt + 3.0 * d_res * Eigen::Vector3d (2, -1, 2).normalized ();
  EXPECT_NEAR (pcl::translationErrorResolutions (est, gt, d_res), 3.0, 1e-9);
  EXPECT_THROW (pcl::translationErrorResolutions (est, gt, 0.0), pcl::BadArgumentException);

  const Eigen::Affine3d gt_pose = Eigen::Translation3d (gt) * Eigen::AngleAxisd (0.3, Eigen::Vector3d::UnitX ());
  const Eigen::Affine3d est_pose = Eigen::Translation3d (est) * Eigen::AngleAxisd (0.3 + M_PI / 180.0, Eigen::Vector3d::UnitX ());
  const auto e = pcl::registrationError (est_pose, gt_pose, d_res);
  EXPECT_NEAR (e.rotation_deg, 1.0, 1e-6);
  EXPECT_NEAR (e.translation_resolutions, 3.0, 1e-9);
}

TEST (RegistrationError, IdenticalViewsOverlapFully)
{
  const auto c = grid (30, 0.001);
  const Eigen::Affine3d pose = Eigen::Translation3d (1, 2, 3) * Eigen::AngleAxisd (0.5, Eigen::Vector3d::UnitY ());
  EXPECT_DOUBLE_EQ (pcl::viewOverlap (c, pose, c, pose, 0.002), 1.0);
}

TEST (RegistrationError, DisjointViewsDoNotOverlap)
{
  const auto c = grid (30, 0.001);
  const Eigen::Affine3d far = Eigen::Affine3d (Eigen::Translation3d (1.0, 0.0, 0.0));
  EXPECT_DOUBLE_EQ (pcl::viewOverlap (c, Eigen::Affine3d::Identity (), c, far, 0.002), 0.0);
}

// Half of the smaller view lies on the larger one: Eq. 14 divides by the smaller vertex count.
TEST (RegistrationError, OverlapCountsTheSmallerView)
{
  const auto big = grid (40, 0.001);     // x, y in [0, 0.039]
  auto small = grid (20, 0.001);         // moved so that half of its columns fall beyond x = 0.039
  const Eigen::Affine3d shift = Eigen::Affine3d (Eigen::Translation3d (0.030, 0.0, 0.0));
  // Columns at x = 0.030 .. 0.039 match (10 of 20); with 0.5 mm tolerance the rest are >= 1 mm away.
  EXPECT_DOUBLE_EQ (pcl::viewOverlap (big, Eigen::Affine3d::Identity (), small, shift, 0.0005), 0.5);
  EXPECT_DOUBLE_EQ (pcl::viewOverlap (small, shift, big, Eigen::Affine3d::Identity (), 0.0005), 0.5);
  EXPECT_THROW (pcl::viewOverlap (big, shift, small, shift, 0.0), pcl::BadArgumentException);
  small.clear ();
  EXPECT_THROW (pcl::viewOverlap (big, shift, small, shift, 0.001), pcl::InvalidScanException);
}

namespace
{
  using Poses = std::vector<Eigen::Affine3d, Eigen::aligned_allocator<Eigen::Affine3d>>;

  /** A 0.1 m cloud of points off the origin, so that rotation and translation both show in it. */
  pcl::PointCloud<pcl::PointXYZ>
  blob ()
  {
    pcl::PointCloud<pcl::PointXYZ> c;
    for (int i = 0; i < 10; ++i)
      for (int j = 0; j < 10; ++j)
        c.push_back (pcl::PointXYZ (0.01f * i, 0.01f * j, 0.002f * ((i * 7 + j * 3) % 5)));
    return c;
  }
}

TEST (RegistrationError, BestFitCommonFrameUndoesAMotionOfTheWholeSet)
{
  const auto cloud = blob ();
  Poses truth, estimates;
  const Eigen::Affine3d g = Eigen::Translation3d (0.3, -0.2, 0.1) * Eigen::AngleAxisd (0.4, Eigen::Vector3d (1, -1, 2).normalized ());
  for (int i = 0; i < 5; ++i)
  {
    truth.push_back (Eigen::Translation3d (0.05 * i, 0.0, 0.01) * Eigen::AngleAxisd (0.5 * i, Eigen::Vector3d::UnitY ()));
    estimates.push_back (g.inverse () * truth.back ());
  }
  const std::vector<const pcl::PointCloud<pcl::PointXYZ>*> views (5, &cloud);
  const Eigen::Affine3d fit = pcl::bestFitCommonFrame (views, estimates, truth);
  EXPECT_TRUE (fit.matrix ().isApprox (g.matrix (), 1e-9));
  EXPECT_THROW (pcl::bestFitCommonFrame (views, estimates, Poses (4)), pcl::BadArgumentException);
  EXPECT_THROW (pcl::bestFitCommonFrame (std::vector<const pcl::PointCloud<pcl::PointXYZ>*> (5, nullptr), estimates, truth),
                pcl::BadArgumentException);
}

TEST (RegistrationError, BestFitCommonFrameChargesATiltedTurntableAxisOnce)
{
  // The estimated turntable turns about an axis 0.3 deg off the true one. Fixing view 0 to its truth
  // leaves the far side 2 x 0.3 deg off; the best common frame leaves every view about 0.3 deg off (a
  // little more, since it also balances the points' displacements).
  const auto cloud = blob ();
  const double tilt = 0.3 * M_PI / 180.0;
  const Eigen::Vector3d axis = Eigen::Vector3d::UnitY (), tilted = Eigen::AngleAxisd (tilt, Eigen::Vector3d::UnitX ()) * axis;
  Poses truth, estimates;
  for (int i = 0; i < 12; ++i)
  {
    truth.emplace_back (Eigen::AngleAxisd (M_PI / 6.0 * i, axis));
    estimates.emplace_back (Eigen::AngleAxisd (M_PI / 6.0 * i, tilted));
  }
  const std::vector<const pcl::PointCloud<pcl::PointXYZ>*> views (12, &cloud);
  EXPECT_NEAR (pcl::rotationErrorDeg (estimates[6].linear (), truth[6].linear ()), 0.6, 1e-6);
  const Eigen::Affine3d fit = pcl::bestFitCommonFrame (views, estimates, truth);
  for (int i = 0; i < 12; ++i)
    EXPECT_NEAR (pcl::rotationErrorDeg ((fit * estimates[i]).linear (), truth[i].linear ()), 0.33, 0.05) << "view " << i;
}
