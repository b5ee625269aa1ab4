/*
 * pcl_tensor: shared helpers for the GoogleTest suite.
 */
#pragma once

#include <gtest/gtest.h>

#include <string>

namespace pcl_tensor_test
{
  /** \brief Path of a file under ../shared/data (third-party scans), or "" when the data is absent. */
  std::string sharedDataPath (const std::string& relative);
}

/** Skip the current test, saying clearly why, when a ../shared/data file is missing. */
#define PCL_TENSOR_REQUIRE_SHARED_DATA(var, relative)                                       \
  const std::string var = pcl_tensor_test::sharedDataPath (relative);                      \
  if (var.empty ())                                                                         \
    GTEST_SKIP () << "SKIPPED: ../shared/data/" << (relative) << " is absent (third-party data)"

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <vector>

namespace pcl_tensor_test
{
  /** \brief The ten raw Stanford bunny scans, relative to ../shared/data. */
  const std::vector<std::string>& bunnyScanNames ();

  /** \brief An organized height field z = f(x, y) of rows x cols samples on a pitch, with smooth random
    * bumps and NaN holes, seeded: a synthetic range image of known geometry for stress tests.
    */
  pcl::PointCloud<pcl::PointXYZ>
  makeHeightField (std::uint32_t seed, int rows, int cols, double pitch, double hole_fraction);
}
