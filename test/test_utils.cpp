#include "test_utils.h"

#include <pcl/common/point_tests.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <set>

namespace pcl_tensor_test
{
  std::string
  sharedDataPath (const std::string& relative)
  {
    const std::string path = std::string (PCL_TENSOR_SHARED_DATA) + "/" + relative;
    return std::ifstream (path).good () ? path : std::string ();
  }

  Eigen::Isometry3d
  randomRigidTransform (std::mt19937& rng, double max_translation)
  {
    std::normal_distribution<double> gauss;
    std::uniform_real_distribution<double> uniform (-max_translation, max_translation);
    // One draw per statement, in gcc's (right-to-left) order of constructor arguments, so that the
    // fixed seeds give the same transforms whichever compiler builds the tests.
    const double qz = gauss (rng), qy = gauss (rng), qx = gauss (rng), qw = gauss (rng);
    Eigen::Quaterniond q (qw, qx, qy, qz);
    q.normalize ();
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity ();
    t.linear () = q.toRotationMatrix ();
    const double tz = uniform (rng), ty = uniform (rng), tx = uniform (rng);
    t.translation () = Eigen::Vector3d (tx, ty, tz);
    return t;
  }

  Eigen::Isometry3d
  randomExactRigidTransform (std::mt19937& rng, double max_translation)
  {
    std::vector<Eigen::Matrix3d> rotations;
    int perm[3] = {0, 1, 2};
    do
      for (int signs = 0; signs < 8; ++signs)
      {
        Eigen::Matrix3d r = Eigen::Matrix3d::Zero ();
        for (int k = 0; k < 3; ++k)
          r (k, perm[k]) = (signs >> k) & 1 ? -1.0 : 1.0;
        if (r.determinant () > 0.0)
          rotations.push_back (r);
      }
    while (std::next_permutation (perm, perm + 3));
    std::uniform_int_distribution<int> pick (0, static_cast<int> (rotations.size ()) - 1);
    const int steps = static_cast<int> (std::floor (max_translation * 1024.0));
    std::uniform_int_distribution<int> shift (-steps, steps);
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity ();
    t.linear () = rotations[pick (rng)];
    const int sz = shift (rng), sy = shift (rng), sx = shift (rng);  // gcc's order, as above
    t.translation () = Eigen::Vector3d (sx, sy, sz) / 1024.0;
    return t;
  }

  double
  meshAreaInCube (const std::vector<Eigen::Vector3d>& vertices, const std::vector<pcl::Vertices>& polygons,
                  const Eigen::Vector3d& origin, const Eigen::Matrix3d& frame, double half_extent)
  {
    double total = 0.0;
    for (const auto& poly : polygons)
    {
      std::vector<Eigen::Vector3d> p;
      for (const auto v : poly.vertices)
        p.push_back (frame * (vertices[v] - origin));
      // Sutherland-Hodgman against the six half-spaces s * u_axis <= half_extent.
      for (int axis = 0; axis < 3 && !p.empty (); ++axis)
        for (const double s : {1.0, -1.0})
        {
          std::vector<Eigen::Vector3d> out;
          for (std::size_t i = 0; i < p.size (); ++i)
          {
            const Eigen::Vector3d& a = p[i];
            const Eigen::Vector3d& b = p[(i + 1) % p.size ()];
            const double da = s * a[axis] - half_extent;
            const double db = s * b[axis] - half_extent;
            if (da <= 0.0)
              out.push_back (a);
            if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0))
              out.push_back (a + (b - a) * (da / (da - db)));
          }
          p.swap (out);
        }
      if (p.size () < 3)
        continue;
      Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
      for (std::size_t i = 1; i + 1 < p.size (); ++i)
        sum += (p[i] - p[0]).cross (p[i + 1] - p[0]);
      total += 0.5 * sum.norm ();
    }
    return total;
  }

  const std::vector<std::string>&
  bunnyScanNames ()
  {
    static const std::vector<std::string> names = {
      "stanford/bunny/bun000.ply", "stanford/bunny/bun045.ply", "stanford/bunny/bun090.ply",
      "stanford/bunny/bun180.ply", "stanford/bunny/bun270.ply", "stanford/bunny/bun315.ply",
      "stanford/bunny/chin.ply",   "stanford/bunny/ear_back.ply", "stanford/bunny/top2.ply",
      "stanford/bunny/top3.ply"};
    return names;
  }

  pcl::PointCloud<pcl::PointXYZ>
  makeHeightField (std::uint32_t seed, int rows, int cols, double pitch, double hole_fraction)
  {
    std::mt19937 rng (seed);
    std::uniform_real_distribution<double> u (0.0, 1.0);
    struct Bump { double x, y, h, w; };
    std::vector<Bump> bumps (6);
    for (auto& b : bumps)
      b = {u (rng) * cols * pitch, u (rng) * rows * pitch, (u (rng) - 0.5) * 8 * pitch, (2 + 8 * u (rng)) * pitch};
    pcl::PointCloud<pcl::PointXYZ> cloud (static_cast<std::uint32_t> (cols), static_cast<std::uint32_t> (rows));
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c)
      {
        const double x = c * pitch, y = r * pitch;
        double z = 0.0;
        for (const auto& b : bumps)
          z += b.h * std::exp (-((x - b.x) * (x - b.x) + (y - b.y) * (y - b.y)) / (2 * b.w * b.w));
        auto& p = cloud.at (c, r);
        if (u (rng) < hole_fraction)
          p.x = p.y = p.z = std::numeric_limits<float>::quiet_NaN ();
        else
          p = pcl::PointXYZ (static_cast<float> (x), static_cast<float> (y), static_cast<float> (z));
      }
    cloud.is_dense = false;
    return cloud;
  }

  pcl::PointCloud<pcl::PointXYZ>
  jittered (const pcl::PointCloud<pcl::PointXYZ>& cloud, double sigma, std::uint32_t seed)
  {
    std::mt19937 rng (seed);
    std::normal_distribution<float> noise (0.0f, static_cast<float> (sigma));
    pcl::PointCloud<pcl::PointXYZ> out = cloud;
    for (auto& p : out)
      if (std::isfinite (p.x))
        p.getVector3fMap () += Eigen::Vector3f (noise (rng), noise (rng), noise (rng));
    return out;
  }

  bool
  consistentlyOriented (const pcl::ScanMesh& mesh)
  {
    std::set<std::pair<pcl::index_t, pcl::index_t>> directed;
    for (const auto& poly : mesh.polygons)
      for (std::size_t e = 0; e < poly.vertices.size (); ++e)
        if (!directed.emplace (poly.vertices[e], poly.vertices[(e + 1) % poly.vertices.size ()]).second)
          return false;
    return true;
  }

  std::string
  writeTempFile (const std::string& name, const std::string& bytes)
  {
    const std::string path = ::testing::TempDir () + name;
    std::ofstream (path, std::ios::binary) << bytes;
    return path;
  }

  void
  expectIdenticalPoints (const pcl::PointCloud<pcl::PointXYZ>& expected, const pcl::PointCloud<pcl::PointXYZ>& actual)
  {
    ASSERT_EQ (expected.width, actual.width);
    ASSERT_EQ (expected.height, actual.height);
    ASSERT_EQ (expected.size (), actual.size ());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < expected.size (); ++i)
    {
      const bool fe = pcl::isXYZFinite (expected[i]), fa = pcl::isXYZFinite (actual[i]);
      if (fe != fa || (fe && std::memcmp (expected[i].data, actual[i].data, 3 * sizeof (float)) != 0))
        ++differing;
    }
    EXPECT_EQ (differing, 0u);
  }

  double
  median (std::vector<double> values)
  {
    std::nth_element (values.begin (), values.begin () + values.size () / 2, values.end ());
    return values[values.size () / 2];
  }

  pcl::ScanMesh
  sweptMesh (const std::function<double (double)>& radius, double h, const std::function<double (const Eigen::Vector3d&)>& bump,
             int rings, int sectors)
  {
    pcl::ScanMesh mesh;
    for (int i = 0; i < rings; ++i)
      for (int j = 0; j < sectors; ++j)
      {
        const double y = -h + 2.0 * h * i / (rings - 1), a = 2.0 * M_PI * j / sectors;
        const Eigen::Vector3d out (std::cos (a), 0.0, std::sin (a));
        Eigen::Vector3d p = radius (y) * out + y * Eigen::Vector3d::UnitY ();
        p += bump (p) * out;
        pcl::PointNormal v;
        v.getVector3fMap () = p.cast<float> ();
        mesh.cloud->push_back (v);
      }
    const auto index = [sectors] (int i, int j) { return i * sectors + (j % sectors); };
    for (int i = 0; i + 1 < rings; ++i)
      for (int j = 0; j < sectors; ++j)
      {
        pcl::Vertices a, b;
        a.vertices = {index (i, j), index (i + 1, j), index (i, j + 1)};
        b.vertices = {index (i, j + 1), index (i + 1, j), index (i + 1, j + 1)};
        mesh.polygons.push_back (a);
        mesh.polygons.push_back (b);
      }
    // Close both ends with a fan about the axis.
    for (const int i : {0, rings - 1})
    {
      pcl::PointNormal centre;
      centre.getVector3fMap () = Eigen::Vector3f (0.0f, i == 0 ? -h : h, 0.0f);
      mesh.cloud->push_back (centre);
      const auto c = static_cast<int> (mesh.cloud->size () - 1);
      for (int j = 0; j < sectors; ++j)
      {
        pcl::Vertices f;
        f.vertices = i == 0 ? pcl::Indices{c, index (i, j), index (i, j + 1)} : pcl::Indices{c, index (i, j + 1), index (i, j)};
        mesh.polygons.push_back (f);
      }
    }
    return mesh;
  }

}
