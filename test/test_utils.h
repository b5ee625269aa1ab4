/*
 * pcl_tensor: shared helpers for the GoogleTest suite.
 */
#pragma once

#include <gtest/gtest.h>
#include <pcl/Vertices.h>
#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace pcl_tensor_test
{
  /** \brief Path of a file under ../shared/data (third-party scans), or "" when the data is absent. */
  std::string sharedDataPath (const std::string& relative);

  /** \brief A random rigid transform: rotation uniform on SO(3) (normalised Gaussian quaternion),
    * translation uniform in [-max_translation, max_translation]^3. */
  Eigen::Isometry3d randomRigidTransform (std::mt19937& rng, double max_translation = 1.0);

  /** \brief A random rigid transform that float coordinates survive exactly: a rotation from the 24
    * rotations of the cube (signed axis permutations with determinant +1) and a translation in
    * multiples of 2^-10 within [-max_translation, max_translation]^3. Applied to coordinates that are
    * multiples of 2^-20 and smaller than 1 in magnitude, the result is again exact in float. */
  Eigen::Isometry3d randomExactRigidTransform (std::mt19937& rng, double max_translation = 1.0);

  /** \brief The median of \a values (the upper one of an even count); \a values must not be empty. */
  double median (std::vector<double> values);

  /** \brief The bit pattern of \a value, for comparisons that must be exact (NaN and -0 included). */
  inline std::uint32_t bits (float value)
  {
    std::uint32_t b;
    std::memcpy (&b, &value, sizeof b);
    return b;
  }

  /** \brief The bit pattern of \a value, for comparisons that must be exact (NaN and -0 included). */
  inline std::uint64_t bits (double value)
  {
    std::uint64_t b;
    std::memcpy (&b, &value, sizeof b);
    return b;
  }

  /** \brief Round \a value to a multiple of \a step (a power of two keeps it exact in float). */
  inline float quantize (float value, double step)
  {
    return static_cast<float> (std::round (static_cast<double> (value) / step) * step);
  }

  /** \brief Area of a triangle mesh inside the cube |u_k| <= half_extent of a local frame, computed by
    * clipping every triangle against the six faces of the cube (independent of the tensor code).
    * \param[in] vertices mesh vertices
    * \param[in] polygons triangles
    * \param[in] origin cube centre
    * \param[in] frame rows x, y, z of the local frame
    * \param[in] half_extent half the cube's edge
    */
  double meshAreaInCube (const std::vector<Eigen::Vector3d>& vertices, const std::vector<pcl::Vertices>& polygons,
                         const Eigen::Vector3d& origin, const Eigen::Matrix3d& frame, double half_extent);
}

/** Skip the current test, saying clearly why, when a ../shared/data file is missing. */
#define PCL_TENSOR_REQUIRE_SHARED_DATA(var, relative)                                       \
  const std::string var = pcl_tensor_test::sharedDataPath (relative);                      \
  if (var.empty ())                                                                         \
    GTEST_SKIP () << "SKIPPED: ../shared/data/" << (relative) << " is absent (third-party data)"

#include <pcl/common/scan_mesh.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <functional>

#include <vector>

namespace pcl_tensor_test
{
  /** \brief The ten raw Stanford bunny scans, relative to ../shared/data. */
  const std::vector<std::string>& bunnyScanNames ();

  /** A closed surface swept about the y axis: radius \a radius(y) over y in [-h, h], on a grid of
    * \a rings x \a sectors vertices, each moved along its outward direction by \a bump(point); both
    * ends closed by a fan. Surfaces of revolution (and, through \a bump, objects that are nearly so)
    * with exact geometry, for known-answer tests of symmetric objects. */
  pcl::ScanMesh
  sweptMesh (const std::function<double (double)>& radius, double h, const std::function<double (const Eigen::Vector3d&)>& bump,
             int rings = 120, int sectors = 240);

  /** \brief An organized height field z = f(x, y) of rows x cols samples on a pitch, with smooth random
    * bumps and NaN holes, seeded: a synthetic range image of known geometry for stress tests.
    */
  pcl::PointCloud<pcl::PointXYZ>
  makeHeightField (std::uint32_t seed, int rows, int cols, double pitch, double hole_fraction);

  /** \brief \a cloud with every finite point moved by Gaussian noise of \a sigma in each coordinate,
    * seeded. Across the lines of sight, as a perspective scan's noise seen along +z, it folds some
    * triangles over so that they face away from the sensor.
    */
  pcl::PointCloud<pcl::PointXYZ>
  jittered (const pcl::PointCloud<pcl::PointXYZ>& cloud, double sigma, std::uint32_t seed);

  /** \brief True when no directed edge occurs twice: the faces are consistently oriented. */
  bool
  consistentlyOriented (const pcl::ScanMesh& mesh);

  /** \brief Write \a bytes to \a name in GoogleTest's temporary folder; returns the path. */
  std::string
  writeTempFile (const std::string& name, const std::string& bytes);

  /** \brief The clouds agree as a reader's output must: same grid, same NaN pattern, the finite
    * points equal bit for bit. */
  void
  expectIdenticalPoints (const pcl::PointCloud<pcl::PointXYZ>& expected, const pcl::PointCloud<pcl::PointXYZ>& actual);
}
