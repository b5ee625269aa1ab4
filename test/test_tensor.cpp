/*
 * Tests of pcl::TensorEstimation (Mian et al. 2006, Section 2).
 */
#include "test_utils.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/features/tensor.h>
#include <pcl/features/tensor_grid.h>
#include <pcl/io/range_scan_io.h>
#include <pcl/simulation/example_object.h>
#include <pcl/surface/scan_preparation.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace
{
  using Cloud = pcl::PointCloud<pcl::PointNormal>;
  using Tensors = pcl::PointCloud<pcl::TensorDescriptor>;
  using Estimation = pcl::TensorEstimation<pcl::PointNormal, pcl::PointNormal, pcl::TensorDescriptor>;

  constexpr double deg = M_PI / 180.0;

  /** The example object, coarse enough to look like a reduced mesh M'_i (642 vertices, 1280 faces). */
  pcl::ScanMesh
  coarseExampleObject ()
  {
    pcl::ExampleObjectParams params;
    params.subdivisions = 3;
    pcl::ScanMesh mesh = pcl::makeExampleObject (params);
    // Vertices on a 2^-20 m lattice (< 1 um): exact in float after randomExactRigidTransform.
    for (auto& p : *mesh.cloud)
    {
      p.x = pcl_tensor_test::quantize (p.x, std::ldexp (1.0, -20));
      p.y = pcl_tensor_test::quantize (p.y, std::ldexp (1.0, -20));
      p.z = pcl_tensor_test::quantize (p.z, std::ldexp (1.0, -20));
    }
    return mesh;
  }

  /** D of the example object (its ellipsoid axes 1 : 0.72 : 0.55 times 0.2 m). */
  pcl::ObjectDimensions
  exampleDimensions ()
  {
    pcl::ObjectDimensions dims;
    dims.D = Eigen::Vector3d (0.2, 0.144, 0.11);
    return dims;
  }

  std::vector<Eigen::Vector3d>
  verticesOf (const Cloud& cloud)
  {
    std::vector<Eigen::Vector3d> v;
    for (const auto& p : cloud)
      v.emplace_back (p.x, p.y, p.z);
    return v;
  }

  Eigen::Matrix3d
  frameOf (const pcl::TensorDescriptor& t)
  {
    Eigen::Matrix3d f;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        f (r, c) = t.rf[3 * r + c];
    return f;
  }

  /** An estimation of \a mesh's tensors with D of the example object. */
  Estimation
  exampleEstimation (const pcl::ScanMesh& mesh)
  {
    Estimation est;
    est.setInputCloud (mesh.cloud);
    est.setInputNormals (mesh.cloud);
    est.setPolygons (mesh.polygons);
    est.setObjectDimensions (exampleDimensions ());
    return est;
  }

  Tensors
  compute (const pcl::ScanMesh& mesh, int grid_size, bool region_growing)
  {
    Estimation est = exampleEstimation (mesh);
    est.setGridSize (grid_size);
    est.setRegionGrowing (region_growing);
    Tensors out;
    est.computeOrThrow (out);
    return out;
  }

  pcl::ScanMesh
  transformed (const pcl::ScanMesh& mesh, const Eigen::Isometry3d& t)
  {
    pcl::ScanMesh out;
    *out.cloud = *mesh.cloud;
    out.polygons = mesh.polygons;
    const Eigen::Matrix3d r = t.linear ();
    for (auto& p : *out.cloud)
    {
      const Eigen::Vector3d q = t * Eigen::Vector3d (p.x, p.y, p.z);
      const Eigen::Vector3d n = r * Eigen::Vector3d (p.normal_x, p.normal_y, p.normal_z);
      p.x = static_cast<float> (q.x ());
      p.y = static_cast<float> (q.y ());
      p.z = static_cast<float> (q.z ());
      p.normal_x = static_cast<float> (n.x ());
      p.normal_y = static_cast<float> (n.y ());
      p.normal_z = static_cast<float> (n.z ());
    }
    return out;
  }

  /** A planar patch z = x tan(alpha) over [-L, L]^2 (grid spacing s, 2M+1 vertices per side), with two
    * pair vertices a = (-u, 0, -u tan alpha) and b = (u, 0, u tan alpha) whose normals are set so that
    * the local frame of Section 2 is the identity: n_a = (0, sin beta, cos beta), n_b = (0, -sin beta,
    * cos beta) give z = (0, 0, 1), x = n_a x n_b / |.| = (1, 0, 0), y = (0, 1, 0); b is above a along z,
    * so the canonical order is (a, b). The other normals are (0, 0, 1). */
  struct TiltedPlane
  {
    pcl::ScanMesh mesh;
    int a = -1;
    int b = -1;
    double pair_distance = 0.0;
  };

  TiltedPlane
  makeTiltedPlane (double half_extent, double alpha, double beta)
  {
    TiltedPlane plane;
    const int m = 6;
    const double s = half_extent / 4.0;  // patch half-size 1.5 h: covers the cube's section of the plane
    const int k = 2;                     // u = 2 s
    const int side = 2 * m + 1;
    for (int j = -m; j <= m; ++j)
      for (int i = -m; i <= m; ++i)
      {
        pcl::PointNormal p;
        p.x = static_cast<float> (i * s);
        p.y = static_cast<float> (j * s);
        p.z = static_cast<float> (i * s * std::tan (alpha));
        p.normal_x = 0.f;
        p.normal_y = 0.f;
        p.normal_z = 1.f;
        plane.mesh.cloud->push_back (p);
      }
    auto id = [=] (int i, int j) { return (j + m) * side + (i + m); };
    for (int j = -m; j < m; ++j)
      for (int i = -m; i < m; ++i)
      {
        pcl::Vertices t1, t2;
        t1.vertices = {id (i, j), id (i + 1, j), id (i + 1, j + 1)};
        t2.vertices = {id (i, j), id (i + 1, j + 1), id (i, j + 1)};
        plane.mesh.polygons.push_back (t1);
        plane.mesh.polygons.push_back (t2);
      }
    plane.a = id (-k, 0);
    plane.b = id (k, 0);
    auto& pa = (*plane.mesh.cloud)[plane.a];
    auto& pb = (*plane.mesh.cloud)[plane.b];
    pa.normal_y = static_cast<float> (std::sin (beta));
    pa.normal_z = static_cast<float> (std::cos (beta));
    pb.normal_y = static_cast<float> (-std::sin (beta));
    pb.normal_z = static_cast<float> (std::cos (beta));
    plane.pair_distance = 2.0 * k * s / std::cos (alpha);
    return plane;
  }

  /** Analytic area of the plane z = x tan(alpha) inside bin (ix, iy, iz) of an N^3 grid of bin size b_s
    * centred at the origin: b_s * |{x in X : x tan(alpha) in Z}| / cos(alpha). */
  double
  analyticPlaneBinArea (int ix, int iy, int iz, int n, double bs, double alpha)
  {
    (void) iy;  // every y slab sees the same strip
    const double x0 = (ix - 0.5 * n) * bs, x1 = x0 + bs;
    const double z0 = (iz - 0.5 * n) * bs, z1 = z0 + bs;
    const double t = std::tan (alpha);
    const double lo = std::max (x0, z0 / t), hi = std::min (x1, z1 / t);
    return hi > lo ? bs * (hi - lo) / std::cos (alpha) : 0.0;
  }

  void
  checkTiltedPlane (int n, bool region_growing, const Eigen::Isometry3d& motion)
  {
    SCOPED_TRACE ("N = " + std::to_string (n) + (region_growing ? ", region growing" : ", brute force"));
    // Dyadic sizes and tan(alpha) = 3/4 keep every vertex exact in float, so the only error left is
    // the tensor code's own double arithmetic.
    const double bs = 1.0 / 128.0, alpha = std::atan (0.75), beta = 20.0 * deg;
    const double h = 0.5 * n * bs;
    TiltedPlane plane = makeTiltedPlane (h, alpha, beta);
    for (const auto& p : *plane.mesh.cloud)  // the construction is exact in float
    {
      ASSERT_EQ (static_cast<double> (p.x) * 0.75, static_cast<double> (p.z));
      ASSERT_EQ (std::fmod (static_cast<double> (p.x) * 4096.0, 1.0), 0.0);
    }
    const pcl::ScanMesh mesh = transformed (plane.mesh, motion);

    Estimation est;
    est.setInputCloud (mesh.cloud);
    est.setInputNormals (mesh.cloud);
    est.setPolygons (mesh.polygons);
    est.setDistanceLimits (0.9 * plane.pair_distance, 1.1 * plane.pair_distance);
    est.setBinSize (bs);
    est.setGridSize (n);
    est.setRegionGrowing (region_growing);
    est.setIndices (pcl::IndicesPtr (new pcl::Indices{plane.a, plane.b}));
    Tensors out;
    est.computeOrThrow (out);
    ASSERT_EQ (out.size (), 1u);
    const auto& t = out[0];
    EXPECT_EQ (t.vertex_a, plane.a);
    EXPECT_EQ (t.vertex_b, plane.b);
    EXPECT_EQ (t.order_ambiguous, 0u);
    EXPECT_NEAR (t.theta_d, 40.0, 1e-4);
    // Frame (Section 2): the identity in the plane's own coordinates, i.e. the motion's rotation.
    const Eigen::Matrix3d expected_frame = motion.linear ().transpose ();
    EXPECT_TRUE (frameOf (t).isApprox (expected_frame, 1e-6)) << frameOf (t) << "\n vs \n" << expected_frame;
    EXPECT_LT ((t.getVector3fMap ().cast<double> () - motion.translation ()).norm (), 1e-6);

    std::vector<float> dense;
    pcl::toDenseTensor (t, dense);
    double total = 0.0, expected_total = 0.0;
    for (int ix = 0; ix < n; ++ix)
      for (int iy = 0; iy < n; ++iy)
        for (int iz = 0; iz < n; ++iz)
        {
          const double expected = analyticPlaneBinArea (ix, iy, iz, n, bs, alpha);
          const double got = dense[(ix * n + iy) * n + iz];
          EXPECT_NEAR (got, expected, 1e-7 * std::max (expected, 1e-3 * bs * bs)) << "bin " << ix << "," << iy << "," << iz;
          total += got;
          expected_total += expected;
        }
    // The cube's section of the plane: |x| <= h (|z| = 0.75 |x| < h) times |y| <= h, over cos alpha.
    EXPECT_NEAR (expected_total, 4.0 * h * h / std::cos (alpha), 1e-12);
    EXPECT_NEAR (total, expected_total, 1e-6 * expected_total);
  }
}

TEST (TensorEstimation, TiltedPlaneMatchesAnalyticBinAreas)
{
  std::mt19937 rng (20061);
  for (const int n : {10, 15})
    for (const bool rg : {true, false})
    {
      checkTiltedPlane (n, rg, Eigen::Isometry3d::Identity ());
      checkTiltedPlane (n, rg, pcl_tensor_test::randomExactRigidTransform (rng, 0.5));
    }
}

namespace
{
  /** Compare the tensors of a mesh and of its moved copy. Returns the worst per-bin difference relative
    * to max(|a|, |b|) and the worst per-tensor L1 difference relative to the tensor's total area. */
  std::pair<double, double>
  compareMovedTensors (const Tensors& a, const Tensors& b, const Eigen::Isometry3d& motion, double frame_tol,
                       std::size_t& flipped)
  {
    double worst_bin = 0.0, worst_l1 = 0.0;
    flipped = 0;
    EXPECT_GT (a.size (), 100u);
    EXPECT_EQ (a.size (), b.size ());
    for (std::size_t k = 0; k < std::min (a.size (), b.size ()); ++k)
    {
      EXPECT_EQ (std::min (a[k].vertex_a, a[k].vertex_b), std::min (b[k].vertex_a, b[k].vertex_b));
      EXPECT_EQ (std::max (a[k].vertex_a, a[k].vertex_b), std::max (b[k].vertex_a, b[k].vertex_b));
      pcl::TensorDescriptor tb = b[k];
      if (tb.vertex_a != a[k].vertex_a)
      {
        // Only an ambiguous order may flip under a rigid motion.
        EXPECT_EQ (a[k].order_ambiguous, 1u) << "tensor " << k;
        EXPECT_EQ (b[k].order_ambiguous, 1u) << "tensor " << k;
        tb = pcl::flipPairOrder (b[k]);
        ++flipped;
      }
      EXPECT_NEAR (a[k].theta_d, b[k].theta_d, 1e-3);
      // The frame moves with the object: rows of B_b = rows of B_a rotated.
      const Eigen::Matrix3d expected_frame = frameOf (a[k]) * motion.linear ().transpose ();
      EXPECT_TRUE (frameOf (tb).isApprox (expected_frame, frame_tol)) << "tensor " << k;
      std::vector<float> da, db;
      pcl::toDenseTensor (a[k], da);
      pcl::toDenseTensor (tb, db);
      double l1 = 0.0, total = 0.0;
      for (std::size_t i = 0; i < da.size (); ++i)
      {
        const double x = da[i], y = db[i];
        l1 += std::abs (x - y);
        total += x;
        if (x != y)
          worst_bin = std::max (worst_bin, std::abs (x - y) / std::max (std::abs (x), std::abs (y)));
      }
      worst_l1 = std::max (worst_l1, l1 / total);
    }
    return {worst_bin, worst_l1};
  }
}

TEST (TensorEstimation, RigidInvariance)
{
  // A random rigid motion that the float input represents exactly (a rotation of the cube and a
  // dyadic translation, on a mesh whose vertices lie on a 2^-20 m lattice): every bin must agree to
  // 1e-5 relative, the frames to 1e-6.
  const pcl::ScanMesh mesh = coarseExampleObject ();
  std::mt19937 rng (4242);
  for (int trial = 0; trial < 3; ++trial)
  {
    const Eigen::Isometry3d motion = pcl_tensor_test::randomExactRigidTransform (rng, 1.0);
    const pcl::ScanMesh moved = transformed (mesh, motion);
    for (const int n : {10, 15})
      for (const bool rg : {true, false})
      {
        SCOPED_TRACE ("N = " + std::to_string (n) + (rg ? ", region growing" : ", brute force"));
        const Tensors a = compute (mesh, n, rg);
        const Tensors b = compute (moved, n, rg);
        std::size_t flipped = 0;
        const auto worst = compareMovedTensors (a, b, motion, 1e-6, flipped);
        EXPECT_LE (worst.first, 1e-5);
        std::cout << "[ RIGID    ] exact motion " << trial << ", N=" << n << (rg ? " RG" : " BF") << ": " << a.size ()
                  << " tensors, " << flipped << " flipped, worst bin " << worst.first << " relative" << std::endl;
      }
  }
}

TEST (TensorEstimation, RigidInvarianceUnderGeneralMotion)
{
  // A general rotation and a translation up to 0.1 m (the Stanford scans' own scale): the moved float
  // input is rounded (~4e-9 m), and a bin that the surface grazes (or a sliver bin) amplifies that
  // without bound, so the bins are compared in L1 over each tensor: they must agree to 1e-5 of the
  // tensor's total area. Pairs and frames must be the same. (With a 1 m translation the rounding is
  // ~3e-8 m and the worst L1 measured 2e-5.)
  const pcl::ScanMesh mesh = coarseExampleObject ();
  std::mt19937 rng (4243);
  const Eigen::Isometry3d motion = pcl_tensor_test::randomRigidTransform (rng, 0.1);
  const pcl::ScanMesh moved = transformed (mesh, motion);
  for (const int n : {10, 15})
  {
    SCOPED_TRACE ("N = " + std::to_string (n));
    const Tensors a = compute (mesh, n, true);
    const Tensors b = compute (moved, n, true);
    std::size_t flipped = 0;
    const auto worst = compareMovedTensors (a, b, motion, 1e-5, flipped);
    EXPECT_LE (worst.second, 1e-5);
    std::cout << "[ RIGID    ] general motion, N=" << n << ": " << a.size () << " tensors, " << flipped
              << " flipped, worst tensor L1 " << worst.second << " relative, worst single bin " << worst.first
              << " relative" << std::endl;
  }
}

TEST (TensorEstimation, BinsSumToTheAreaInsideTheCube)
{
  const pcl::ScanMesh mesh = coarseExampleObject ();
  const std::vector<Eigen::Vector3d> v = verticesOf (*mesh.cloud);
  for (const int n : {10, 15})
    for (const bool rg : {false, true})
    {
      SCOPED_TRACE ("N = " + std::to_string (n) + (rg ? ", region growing" : ", brute force"));
      const Tensors tensors = compute (mesh, n, rg);
      ASSERT_GT (tensors.size (), 100u);
      std::size_t equal = 0;
      for (std::size_t k = 0; k < tensors.size (); ++k)
      {
        const auto& t = tensors[k];
        double sum = 0.0;
        for (const float a : t.bin_area)
          sum += a;
        const double h = 0.5 * t.grid_size * static_cast<double> (t.bin_size);
        const double cube = pcl_tensor_test::meshAreaInCube (v, mesh.polygons, t.getVector3fMap ().cast<double> (),
                                                             frameOf (t), h);
        ASSERT_GT (cube, 0.0);
        // Region growing may only miss surface, never add any.
        EXPECT_LE (sum, cube * (1.0 + 1e-6)) << "tensor " << k;
        if (std::abs (sum - cube) <= 1e-6 * cube)
          ++equal;
        else if (!rg)
          ADD_FAILURE () << "tensor " << k << ": bins sum to " << sum << ", the cube holds " << cube;
      }
      std::cout << "[ AREA     ] N=" << n << (rg ? " region growing: " : " brute force: ") << equal << " / "
                << tensors.size () << " tensors sum to the area inside their cube" << std::endl;
    }
}

TEST (TensorEstimation, EachBinHoldsTheAreaInsideIt)
{
  // Bin by bin against an independent reference: the mesh clipped to that bin's own cube. Guards any
  // faster way of splitting the faces among the bins.
  const pcl::ScanMesh mesh = coarseExampleObject ();
  const std::vector<Eigen::Vector3d> v = verticesOf (*mesh.cloud);
  for (const int n : {5, 10})
  {
    const Tensors tensors = compute (mesh, n, false);
    ASSERT_GT (tensors.size (), 100u);
    for (std::size_t k = 0; k < tensors.size (); k += tensors.size () / 4)
    {
      SCOPED_TRACE ("N = " + std::to_string (n) + ", tensor " + std::to_string (k));
      const auto& t = tensors[k];
      const double bs = t.bin_size;
      const Eigen::Vector3d origin = t.getVector3fMap ().cast<double> ();
      // Orthonormal in double: the reference places each bin's cube through frame^T.
      Eigen::Matrix3d frame = frameOf (t);
      const Eigen::Vector3d x = frame.row (0).normalized ();
      const Eigen::Vector3d z = (frame.row (2).transpose () - frame.row (2).dot (x) * x).normalized ();
      frame.row (0) = x;
      frame.row (1) = z.cross (x);
      frame.row (2) = z;
      // Local bounding boxes, to hand each bin's reference only the faces that can meet it.
      std::vector<Eigen::Vector3d> lo, hi;
      for (const auto& poly : mesh.polygons)
      {
        Eigen::Vector3d l = Eigen::Vector3d::Constant (1e300), h = -l;
        for (const auto i : poly.vertices)
        {
          const Eigen::Vector3d p = frame * (v[i] - origin);
          l = l.cwiseMin (p);
          h = h.cwiseMax (p);
        }
        lo.push_back (l);
        hi.push_back (h);
      }
      // The grid itself, with the very origin and frame of the reference (the tensor stores them in float).
      pcl::TensorSurfaceGrid grid;
      grid.setMesh (v, mesh.polygons);
      grid.setGrid (n, bs);
      std::vector<std::uint16_t> bin_index;
      std::vector<float> bin_area;
      grid.computeBins (origin, frame, -1, -1, bin_index, bin_area);
      std::map<int, float> stored;
      for (std::size_t b = 0; b < bin_index.size (); ++b)
        stored[bin_index[b]] = bin_area[b];
      for (int bin = 0; bin < n * n * n; ++bin)
      {
        const Eigen::Vector3d centre =
            (Eigen::Vector3d (bin / (n * n), (bin / n) % n, bin % n) - Eigen::Vector3d::Constant (0.5 * (n - 1))) * bs;
        std::vector<pcl::Vertices> near;
        for (std::size_t f = 0; f < mesh.polygons.size (); ++f)
          if (((hi[f] - centre).array () >= -0.5 * bs).all () && ((lo[f] - centre).array () <= 0.5 * bs).all ())
            near.push_back (mesh.polygons[f]);
        const double expected = pcl_tensor_test::meshAreaInCube (v, near, origin + frame.transpose () * centre, frame,
                                                                 0.5 * bs);
        const auto it = stored.find (bin);
        const double area = it == stored.end () ? 0.0 : it->second;
        if (it == stored.end () || expected == 0.0)
          EXPECT_LT (std::max (area, expected), 1e-6 * bs * bs) << "bin " << bin;
        else
          EXPECT_NEAR (area, expected, 1e-6 * expected + 1e-9 * bs * bs) << "bin " << bin;
      }
    }
  }
}

TEST (TensorEstimation, PairsObeyTheConstraints)
{
  const pcl::ScanMesh mesh = coarseExampleObject ();
  const pcl::ObjectDimensions dims = exampleDimensions ();
  const std::vector<Eigen::Vector3d> v = verticesOf (*mesh.cloud);
  std::vector<Eigen::Vector3d> nrm;
  for (const auto& p : *mesh.cloud)
    nrm.push_back (Eigen::Vector3d (p.normal_x, p.normal_y, p.normal_z).normalized ());
  const int nv = static_cast<int> (v.size ());
  auto angle = [&nrm] (int i, int j) { return std::atan2 (nrm[i].cross (nrm[j]).norm (), nrm[i].dot (nrm[j])) / deg; };

  // Independent, brute-force partner lists: the 3 closest valid partners of every vertex.
  std::vector<std::set<int>> closest (nv);
  for (int i = 0; i < nv; ++i)
  {
    std::vector<std::pair<double, int>> valid;
    for (int j = 0; j < nv; ++j)
    {
      const double d = (v[i] - v[j]).norm ();
      const double th = angle (i, j);
      if (j != i && d >= dims.dMin () && d <= dims.dMax () && th > 5.0 && th <= 175.0)
        valid.emplace_back (d, j);
    }
    std::sort (valid.begin (), valid.end ());
    for (std::size_t k = 0; k < std::min<std::size_t> (3, valid.size ()); ++k)
      closest[i].insert (valid[k].second);
  }
  std::set<std::pair<int, int>> expected;
  std::set<std::pair<int, int>> expected_mutual;
  for (int i = 0; i < nv; ++i)
    for (const int j : closest[i])
    {
      expected.insert ({std::min (i, j), std::max (i, j)});
      if (closest[j].count (i))
        expected_mutual.insert ({std::min (i, j), std::max (i, j)});
    }

  for (const auto pairing : {pcl::TensorPairing::EITHER, pcl::TensorPairing::MUTUAL})
  {
    Estimation est;
    est.setInputCloud (mesh.cloud);
    est.setInputNormals (mesh.cloud);
    est.setPolygons (mesh.polygons);
    est.setObjectDimensions (dims);
    est.setPairing (pairing);
    Tensors out;
    est.computeOrThrow (out);
    const bool mutual = pairing == pcl::TensorPairing::MUTUAL;
    std::set<std::pair<int, int>> got;
    std::map<int, int> per_vertex;
    for (const auto& t : out)
    {
      const int a = t.vertex_a, b = t.vertex_b;
      const double d = (v[a] - v[b]).norm ();
      EXPECT_GE (d, dims.dMin ());
      EXPECT_LE (d, dims.dMax ());
      EXPECT_GT (t.theta_d, 5.0);
      EXPECT_NEAR (t.theta_d, angle (a, b), 1e-4);
      if (mutual)
        EXPECT_TRUE (closest[a].count (b) && closest[b].count (a));
      else
        EXPECT_TRUE (closest[a].count (b) || closest[b].count (a));
      EXPECT_TRUE (got.insert ({std::min (a, b), std::max (a, b)}).second) << "pair " << a << "," << b << " twice";
      ++per_vertex[a];
      ++per_vertex[b];
      // Frame: orthonormal, right-handed, z along n_a + n_b, x along n_a x n_b, canonical order.
      const Eigen::Matrix3d f = frameOf (t);
      EXPECT_TRUE ((f * f.transpose ()).isApprox (Eigen::Matrix3d::Identity (), 1e-6));
      EXPECT_NEAR (f.determinant (), 1.0, 1e-6);
      EXPECT_GT (f.row (2).dot ((nrm[a] + nrm[b]).normalized ()), 1.0 - 1e-6);
      EXPECT_GT (f.row (0).dot (nrm[a].cross (nrm[b]).normalized ()), 1.0 - 1e-6);
      EXPECT_GE (f.row (2).dot (v[b] - v[a]), -1e-9);
      EXPECT_LT ((t.getVector3fMap ().cast<double> () - 0.5 * (v[a] + v[b])).norm (), 1e-6);
    }
    EXPECT_EQ (got, mutual ? expected_mutual : expected);
    EXPECT_LE (out.size (), 3u * v.size ());
    if (mutual)
    {
      for (const auto& pv : per_vertex)
        EXPECT_LE (pv.second, 3);
    }
    std::cout << "[ PAIRS    ] " << (mutual ? "mutual" : "either") << ": " << out.size () << " pairs for " << nv
              << " vertices" << std::endl;
  }
}

TEST (TensorEstimation, BadInputGivesClearErrors)
{
  const pcl::ScanMesh mesh = coarseExampleObject ();
  auto configured = [&mesh] () { return exampleEstimation (mesh); };
  Tensors out;

  {  // A mesh without polygons.
    Estimation est = configured ();
    est.setPolygons ({});
    EXPECT_THROW (est.computeOrThrow (out), pcl::InvalidScanException);
    EXPECT_NE (est.getLastError ().find ("no polygons"), std::string::npos) << est.getLastError ();
    out.resize (5);
    est.compute (out);  // the PCL way: an error message and an empty cloud
    EXPECT_TRUE (out.empty ());
    EXPECT_EQ (est.getLastErrorKind (), Estimation::ErrorKind::INVALID_SCAN);
  }
  {  // Normals of zero length.
    Cloud::Ptr cloud (new Cloud (*mesh.cloud));
    (*cloud)[7].normal_x = (*cloud)[7].normal_y = (*cloud)[7].normal_z = 0.f;
    Estimation est = configured ();
    est.setInputCloud (cloud);
    est.setInputNormals (cloud);
    EXPECT_THROW (est.computeOrThrow (out), pcl::InvalidScanException);
    EXPECT_NE (est.getLastError ().find ("zero length"), std::string::npos) << est.getLastError ();
  }
  {  // D of zero.
    Estimation est;
    EXPECT_THROW (est.setObjectDimensions (pcl::ObjectDimensions ()), pcl::BadArgumentException);
  }
  {  // N = 0, and N too large for 16-bit bin indices.
    Estimation est;
    EXPECT_THROW (est.setGridSize (0), pcl::BadArgumentException);
    EXPECT_THROW (est.setGridSize (41), pcl::BadArgumentException);
    EXPECT_NO_THROW (est.setGridSize (40));
  }
  {  // No distance limits or bin size.
    Estimation est;
    est.setInputCloud (mesh.cloud);
    est.setInputNormals (mesh.cloud);
    est.setPolygons (mesh.polygons);
    EXPECT_THROW (est.computeOrThrow (out), pcl::BadArgumentException);
  }
  {  // Other bad parameters.
    Estimation est;
    EXPECT_THROW (est.setDistanceLimits (0.0, 1.0), pcl::BadArgumentException);
    EXPECT_THROW (est.setDistanceLimits (2.0, 1.0), pcl::BadArgumentException);
    EXPECT_THROW (est.setBinSize (-1.0), pcl::BadArgumentException);
    EXPECT_THROW (est.setMinNormalAngle (180.0), pcl::BadArgumentException);
    EXPECT_THROW (est.setPartnersPerVertex (0), pcl::BadArgumentException);
  }
  {  // Normals that do not match the vertices, a non-triangle, an index out of range.
    Estimation est = configured ();
    Cloud::Ptr fewer (new Cloud (*mesh.cloud));
    fewer->resize (fewer->size () - 1);
    est.setInputNormals (fewer);
    EXPECT_THROW (est.computeOrThrow (out), pcl::InvalidScanException);

    Estimation quad = configured ();
    auto polys = mesh.polygons;
    polys[3].vertices.push_back (0);
    quad.setPolygons (polys);
    EXPECT_THROW (quad.computeOrThrow (out), pcl::InvalidScanException);

    Estimation range = configured ();
    polys = mesh.polygons;
    polys[3].vertices[1] = static_cast<pcl::index_t> (mesh.cloud->size ());
    range.setPolygons (polys);
    EXPECT_THROW (range.computeOrThrow (out), pcl::InvalidScanException);
  }
  {  // No input at all.
    Estimation est;
    est.setObjectDimensions (exampleDimensions ());
    EXPECT_THROW (est.computeOrThrow (out), pcl::BadArgumentException);
  }
}

TEST (TensorEstimation, DefaultsAreThePapers)
{
  Estimation est;
  EXPECT_EQ (est.getGridSize (), 10);
  EXPECT_EQ (est.getMinNormalAngle (), 5.0);
  EXPECT_EQ (est.getPartnersPerVertex (), 3);
  EXPECT_FALSE (est.getRegionGrowing ());      // brute force: exact and faster at 400 faces, see the class
  EXPECT_TRUE (est.getSeedEveryComponent ());  // extensions of the paper's region growing, see the class
  EXPECT_EQ (est.getGrowthMargin (), 2.0);
  EXPECT_EQ (est.getMaxNormalAngle (), 175.0);
  EXPECT_EQ (est.getOrderAmbiguityAngle (), 5.0);
  EXPECT_EQ (est.getPairing (), pcl::TensorPairing::EITHER);
  est.setObjectDimensions (exampleDimensions ());
  const double mean = exampleDimensions ().mean ();
  EXPECT_DOUBLE_EQ (est.getMinDistance (), mean / 6.0);
  EXPECT_DOUBLE_EQ (est.getMaxDistance (), mean / 4.0);
  EXPECT_DOUBLE_EQ (est.getBinSize (), mean / 30.0);
}

TEST (TensorEstimation, SparseStorageSavesMemory)
{
  const Tensors tensors = compute (coarseExampleObject (), 10, true);
  const pcl::TensorMemoryUsage m = pcl::computeTensorMemoryUsage (tensors);
  EXPECT_EQ (m.tensors, tensors.size ());
  EXPECT_EQ (m.dense_bin_bytes, tensors.size () * 1000u * sizeof (float));
  EXPECT_EQ (m.sparse_bin_bytes, m.non_zero_bins * 6u);
  EXPECT_LT (m.sparse_bytes, m.dense_bytes);
  std::cout << "[ MEMORY   ] " << tensors.size () << " tensors, " << static_cast<double> (m.non_zero_bins) / m.tensors
            << " non-zero bins each; sparse " << static_cast<double> (m.sparse_bytes) / m.tensors << " B/tensor, dense "
            << static_cast<double> (m.dense_bytes) / m.tensors << " B/tensor, saved " << 100.0 * m.savedFraction ()
            << "%" << std::endl;
}

TEST (TensorEstimation, RegionGrowingAgreesWithBruteForceOnBunnyScans)
{
  PCL_TENSOR_REQUIRE_SHARED_DATA (first, "stanford/bunny/bun000.ply");
  (void) first;
  std::vector<pcl::io::RangeScan> scans;
  std::vector<const pcl::PointCloud<pcl::PointXYZ>*> views;
  for (const auto& name : pcl_tensor_test::bunnyScanNames ())
  {
    const std::string path = pcl_tensor_test::sharedDataPath (name);
    if (path.empty ())
      continue;
    scans.push_back (pcl::io::loadRangeScan (path));
  }
  for (const auto& s : scans)
    views.push_back (s.cloud.get ());
  const pcl::ObjectDimensions dims = pcl::computeObjectDimensions<pcl::PointXYZ> (views);  // Eq. 1
  // Region growing seeded in every component that can reach the grid (default), and with the paper's
  // single seed, against brute force.
  std::size_t total = 0, differing_total = 0, differing_single = 0, ambiguous = 0;
  double missing_single = 0.0;
  for (const int n : {10, 15})
    for (std::size_t v = 0; v < scans.size (); ++v)
    {
      const pcl::PreparedScan prepared = pcl::prepareScan (*scans[v].cloud, scans[v].viewpoint);
      Tensors rg, single, bf;
      Estimation est;
      est.setInputCloud (prepared.reduced.cloud);
      est.setInputNormals (prepared.reduced.cloud);
      est.setPolygons (prepared.reduced.polygons);
      est.setObjectDimensions (dims);
      est.setGridSize (n);
      est.setRegionGrowing (true);
      est.computeOrThrow (rg);
      est.setSeedEveryComponent (false);
      est.setGrowthMargin (0.0);
      est.computeOrThrow (single);
      est.setRegionGrowing (false);
      est.computeOrThrow (bf);
      ASSERT_GT (rg.size (), 0u);
      if (v == 0)
      {
        // On real data too, brute force gives exactly the area inside each grid cube.
        const std::vector<Eigen::Vector3d> vertices = verticesOf (*prepared.reduced.cloud);
        for (const auto& t : bf)
        {
          double sum = 0.0;
          for (const float a : t.bin_area)
            sum += a;
          const double cube = pcl_tensor_test::meshAreaInCube (vertices, prepared.reduced.polygons,
                                                               t.getVector3fMap ().cast<double> (), frameOf (t),
                                                               0.5 * n * static_cast<double> (t.bin_size));
          EXPECT_NEAR (sum, cube, 1e-6 * cube);
        }
      }
      const std::size_t differing = pcl::countDifferingTensors (rg, bf, 1e-6);
      const std::size_t differing1 = pcl::countDifferingTensors (single, bf, 1e-6);
      for (std::size_t k = 0; k < bf.size (); ++k)
      {
        double a = 0.0, b = 0.0;
        for (const float x : single[k].bin_area)
          a += x;
        for (const float x : bf[k].bin_area)
          b += x;
        missing_single += (b - a) / b;
      }
      total += rg.size ();
      for (const auto& t : bf)
        ambiguous += t.order_ambiguous;
      differing_total += differing;
      differing_single += differing1;
      std::cout << "[ RG vs BF ] N=" << n << " " << pcl_tensor_test::bunnyScanNames ()[v] << ": "
                << prepared.reduced.polygons.size () << " faces, " << rg.size () << " tensors; differ: "
                << differing << " (every component), " << differing1 << " (single seed)" << std::endl;
    }
  const double agree = 1.0 - static_cast<double> (differing_total) / static_cast<double> (total);
  const double agree_single = 1.0 - static_cast<double> (differing_single) / static_cast<double> (total);
  std::cout << "[ RG vs BF ] region growing agrees with brute force on " << 100.0 * agree << "% of " << total
            << " tensors (every component seeded); the paper's single seed on " << 100.0 * agree_single
            << "%, missing " << 100.0 * missing_single / total << "% of the area on average; "
            << 100.0 * static_cast<double> (ambiguous) / total << "% of the tensors have an ambiguous pair order"
            << std::endl;
  EXPECT_GE (agree, 0.99);
}

namespace
{
  /** Batch \a batch of \a batches from \a est. */
  Tensors
  computeBatch (Estimation& est, int batches, int batch)
  {
    est.setPairBatch (batches, batch);
    Tensors out;
    est.computeOrThrow (out);
    return out;
  }

  /** \a est's batch 0 of 2 equals a new estimation's on \a mesh with d_max \a d_max, bit for bit. */
  void
  expectSameAsNew (Estimation& est, const pcl::ScanMesh& mesh, double d_max)
  {
    Estimation fresh = exampleEstimation (mesh);
    fresh.setDistanceLimits (exampleDimensions ().dMin (), d_max);
    const Tensors expected = computeBatch (fresh, 2, 0);
    const Tensors got = computeBatch (est, 2, 0);
    ASSERT_GT (expected.size (), 10u);
    ASSERT_EQ (got.size (), expected.size ());
    for (std::size_t k = 0; k < got.size (); ++k)
    {
      EXPECT_EQ (got[k].vertex_a, expected[k].vertex_a);
      EXPECT_EQ (got[k].vertex_b, expected[k].vertex_b);
      EXPECT_EQ (got[k].bin_index, expected[k].bin_index);
      EXPECT_EQ (got[k].bin_area, expected[k].bin_area);
    }
  }
}

TEST (TensorEstimation, OneEstimationForEveryBatchRedoesWhatChanged)
{
  // The pipeline computes a view's batches with one estimation, which meshes and pairs once; a
  // changed cloud (in place, same pointer), setting or mesh must still give what a new one gives.
  pcl::ScanMesh mesh = coarseExampleObject ();
  const double d_max = exampleDimensions ().dMax ();
  Estimation est = exampleEstimation (mesh);
  const Tensors first = computeBatch (est, 2, 1);
  expectSameAsNew (est, mesh, d_max);
  EXPECT_EQ (computeBatch (est, 2, 1).size (), first.size ());

  // Stretched in place: other distances, so other pairs, and the search tree must follow.
  for (auto& p : *mesh.cloud)
    p.x *= 1.25f;
  expectSameAsNew (est, mesh, d_max);

  est.setDistanceLimits (exampleDimensions ().dMin (), 0.8 * d_max);
  expectSameAsNew (est, mesh, 0.8 * d_max);

  mesh.polygons.resize (mesh.polygons.size () / 2);
  est.setPolygons (mesh.polygons);
  expectSameAsNew (est, mesh, 0.8 * d_max);
}

TEST (TensorEstimation, PairBatchesPartitionTheTensors)
{
  // Three batches hold every tensor of the whole view exactly once, each the same tensor.
  const pcl::ScanMesh mesh = coarseExampleObject ();
  const Tensors all = compute (mesh, 10, false);
  ASSERT_GT (all.size (), 30u);
  std::size_t total = 0;
  for (int batch = 0; batch < 3; ++batch)
  {
    Estimation est = exampleEstimation (mesh);
    est.setPairBatch (3, batch);
    Tensors part;
    est.computeOrThrow (part);
    total += part.size ();
    for (std::size_t k = 0; k < part.size (); ++k)
    {
      const auto& whole = all[static_cast<std::size_t> (batch) + 3 * k];
      EXPECT_EQ (part[k].vertex_a, whole.vertex_a);
      EXPECT_EQ (part[k].vertex_b, whole.vertex_b);
      EXPECT_EQ (part[k].bin_index, whole.bin_index);
    }
  }
  EXPECT_EQ (total, all.size ());
  Estimation est;
  EXPECT_THROW (est.setPairBatch (0, 0), pcl::BadArgumentException);
  EXPECT_THROW (est.setPairBatch (3, 3), pcl::BadArgumentException);
  EXPECT_THROW (est.setPairBatch (3, -1), pcl::BadArgumentException);
}
