/*
 * pcl_tensor: tests of the per-view cache (TensorViewCache), its keys and hashes, and AtomicFileWriter.
 */
#include "test_utils.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/io/atomic_file.h>
#include <pcl/io/content_hash.h>
#include <pcl/io/cached_tensor_view.h>
#include <pcl/io/range_grid_ply.h>
#include <pcl/io/scan_sensor_cache.h>
#include <pcl/io/tensor_view_cache.h>
#include <pcl/registration/registration_error.h>
#include <pcl/registration/tensor_registration.h>
#include <pcl/simulation/example_object.h>
#include <pcl/simulation/synthetic_views.h>
#include <pcl/simulation/view_set.h>

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <set>
#include <thread>
#include <tuple>

namespace pcl
{
  namespace io
  {
    /** GoogleTest prints states by name. */
    void
    PrintTo (CacheEntryState state, std::ostream* os)
    {
      *os << toString (state);
    }
  }
}

namespace
{
  namespace fs = std::filesystem;
  using pcl::io::CacheEntryKind;
  using pcl::io::CacheEntryState;
  using pcl::io::TensorViewCache;
  using pcl::io::TensorViewCacheKey;
  using pcl::registration::TensorView;
  using Tensors = pcl::PointCloud<pcl::TensorDescriptor>;

  /** Two views of the built-in object 30 degrees apart (200 x 200), prepared with the registration's
    * defaults, D from both (Eq. 1) and their tensors: what a cache holds. */
  struct PreparedPair
  {
    std::vector<pcl::SyntheticView> rendered;
    std::vector<TensorView::Ptr> views;  // with tensors
    pcl::ObjectDimensions dims;
    pcl::registration::TensorRegistrationParams params;
  };

  const PreparedPair&
  preparedPair ()
  {
    static const PreparedPair pair = [] {
      PreparedPair p;
      pcl::SyntheticViewParams render;
      render.camera.width = render.camera.height = 200;
      p.rendered = pcl::renderSyntheticViews (pcl::makeExampleObject (), pcl::makeRingViewDirections (2, 30.0), render);
      std::vector<TensorView::Ptr> meshes;
      for (const auto& r : p.rendered)
        meshes.push_back (pcl::registration::prepareTensorView (*r.view.cloud, r.view.viewpoint, p.params.preparation));
      p.dims = pcl::computeObjectDimensions<pcl::PointNormal> ({meshes[0]->scan->fine.cloud.get (),
                                                                meshes[1]->scan->fine.cloud.get ()});
      for (const auto& m : meshes)
        p.views.push_back (pcl::registration::withTensors (*m, p.dims, p.params));
      return p;
    } ();
    return pair;
  }

  const TensorViewCacheKey kKey{0x1234567890abcdefull, 0xfedcba0987654321ull};

  using pcl_tensor_test::bits;

  template <typename Matrix> void
  expectSameBits (const Matrix& expected, const Matrix& actual, const char* what)
  {
    ASSERT_EQ (expected.size (), actual.size ()) << what;
    for (Eigen::Index i = 0; i < expected.size (); ++i)
      EXPECT_EQ (bits (expected.data ()[i]), bits (actual.data ()[i])) << what << " [" << i << "]";
  }

  template <typename PointT> void
  expectSameCloudMeta (const pcl::PointCloud<PointT>& expected, const pcl::PointCloud<PointT>& actual)
  {
    EXPECT_EQ (expected.width, actual.width);
    EXPECT_EQ (expected.height, actual.height);
    EXPECT_EQ (expected.is_dense, actual.is_dense);
    EXPECT_EQ (expected.header.frame_id, actual.header.frame_id);
    EXPECT_EQ (expected.header.stamp, actual.header.stamp);
    EXPECT_EQ (expected.header.seq, actual.header.seq);
    expectSameBits (expected.sensor_origin_, actual.sensor_origin_, "sensor origin");
    expectSameBits (expected.sensor_orientation_.coeffs (), actual.sensor_orientation_.coeffs (), "sensor orientation");
  }

  /** Every field of the two meshes equal bit for bit (NaN normals included). */
  void
  expectSameMesh (const pcl::ScanMesh& expected, const pcl::ScanMesh& actual)
  {
    EXPECT_EQ (expected.viewpoint.model, actual.viewpoint.model);
    expectSameBits (expected.viewpoint.sensor_pose.matrix (), actual.viewpoint.sensor_pose.matrix (), "sensor pose");
    expectSameCloudMeta (*expected.cloud, *actual.cloud);
    ASSERT_EQ (expected.cloud->size (), actual.cloud->size ());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < expected.cloud->size (); ++i)
    {
      const auto& a = (*expected.cloud)[i];
      const auto& b = (*actual.cloud)[i];
      const float fa[] = {a.x, a.y, a.z, a.normal_x, a.normal_y, a.normal_z, a.curvature};
      const float fb[] = {b.x, b.y, b.z, b.normal_x, b.normal_y, b.normal_z, b.curvature};
      for (int k = 0; k < 7; ++k)
        differing += bits (fa[k]) != bits (fb[k]);
    }
    EXPECT_EQ (differing, 0u);
    ASSERT_EQ (expected.polygons.size (), actual.polygons.size ());
    for (std::size_t i = 0; i < expected.polygons.size (); ++i)
      ASSERT_EQ (expected.polygons[i].vertices, actual.polygons[i].vertices) << "polygon " << i;
  }

  void
  expectSameTensors (const Tensors& expected, const Tensors& actual)
  {
    expectSameCloudMeta (expected, actual);
    ASSERT_EQ (expected.size (), actual.size ());
    for (std::size_t i = 0; i < expected.size (); ++i)
    {
      const auto& a = expected[i];
      const auto& b = actual[i];
      std::vector<std::uint32_t> fa{bits (a.x), bits (a.y), bits (a.z), bits (a.theta_d), bits (a.bin_size)};
      std::vector<std::uint32_t> fb{bits (b.x), bits (b.y), bits (b.z), bits (b.theta_d), bits (b.bin_size)};
      for (int k = 0; k < 9; ++k)
      {
        fa.push_back (bits (a.rf[k]));
        fb.push_back (bits (b.rf[k]));
      }
      ASSERT_EQ (fa, fb) << "tensor " << i;
      ASSERT_EQ (std::make_tuple (a.vertex_a, a.vertex_b, a.grid_size, a.order_ambiguous),
                 std::make_tuple (b.vertex_a, b.vertex_b, b.grid_size, b.order_ambiguous)) << "tensor " << i;
      ASSERT_EQ (a.bin_index, b.bin_index) << "tensor " << i;
      ASSERT_EQ (a.bin_area.size (), b.bin_area.size ()) << "tensor " << i;
      for (std::size_t k = 0; k < a.bin_area.size (); ++k)
        ASSERT_EQ (bits (a.bin_area[k]), bits (b.bin_area[k])) << "tensor " << i << " bin " << k;
    }
  }

  std::string
  readBytes (const std::string& path)
  {
    std::ifstream in (path, std::ios::binary);
    return {std::istreambuf_iterator<char> (in), std::istreambuf_iterator<char> ()};
  }

  void
  writeBytes (const std::string& path, const std::string& bytes)
  {
    std::ofstream (path, std::ios::binary | std::ios::trunc) << bytes;
  }

  /** A fresh, empty folder per test, removed afterwards. */
  class TensorViewCacheTest : public ::testing::Test
  {
    protected:
      void
      SetUp () override
      {
        const auto* info = ::testing::UnitTest::GetInstance ()->current_test_info ();
        dir_ = fs::path (::testing::TempDir ()) /
               ("tensor_view_cache_" + std::string (info->name ()) + "_" + std::to_string (::getpid ()));
        fs::remove_all (dir_);
        fs::create_directories (dir_);
      }

      void
      TearDown () override
      {
        std::error_code ignored;
        fs::remove_all (dir_, ignored);
      }

      /** Three views of a ring of the example object, 30 degrees apart, written as range-grid PLY files
        * in the test's folder: the inputs (file name, cloud, sensor) and, in \a rendered, the truth. */
      std::vector<pcl::registration::MultiviewInput>
      ringFiles (std::vector<pcl::SyntheticView>& rendered) const
      {
        pcl::SyntheticViewParams render;
        render.camera.width = render.camera.height = 200;
        rendered = pcl::renderSyntheticViews (pcl::makeExampleObject (), pcl::makeRingViewDirections (3, 30.0), render);
        std::vector<pcl::registration::MultiviewInput> files;
        for (std::size_t i = 0; i < rendered.size (); ++i)
        {
          const std::string path = (dir_ / ("view" + std::to_string (i) + ".ply")).string ();
          pcl::io::saveRangeGridPLY (path, *rendered[i].view.cloud);
          files.push_back ({path, rendered[i].view.cloud, rendered[i].view.viewpoint, nullptr});
        }
        return files;
      }

      /** A cache holding view \a i's meshes and tensors under kKey, as id "view". */
      TensorViewCache
      filledCache (int i = 0) const
      {
        TensorViewCache cache ((dir_ / "cache").string ());
        const auto& pair = preparedPair ();
        cache.saveView ("view", kKey, *pair.views[i]);
        cache.saveTensors ("view", kKey, pair.dims, hashTensors (), *pair.views[i]->tensors);
        return cache;
      }

      static std::uint64_t
      hashTensors ()
      {
        return pcl::io::hashTensorParameters (preparedPair ().params);
      }

      /** Each lookup of entry \a kind, under the key, D and tensor hash it was saved with. */
      static CacheEntryState
      lookup (const TensorViewCache& cache, CacheEntryKind kind)
      {
        if (kind == CacheEntryKind::TENSORS)
        {
          Tensors::Ptr tensors;
          const auto state = cache.loadTensors ("view", kKey, preparedPair ().dims, hashTensors (), tensors);
          EXPECT_EQ (state == CacheEntryState::VALID, tensors != nullptr) << "output set only when valid";
          return state;
        }
        TensorView view;
        Eigen::Vector3d extents = Eigen::Vector3d::Constant (-1.0);
        const auto state = cache.loadView ("view", kKey, view);
        EXPECT_EQ (state, cache.loadExtents ("view", kKey, extents)) << "loadView and loadExtents agree";
        EXPECT_EQ (state == CacheEntryState::VALID, view.scan != nullptr) << "output set only when valid";
        EXPECT_EQ (state == CacheEntryState::VALID, extents.x () != -1.0) << "output set only when valid";
        return state;
      }

      /** The lookup of entry \a kind once byte \a at of its bytes \a good is xor-ed with \a mask. */
      static CacheEntryState
      lookupFlipped (const TensorViewCache& cache, CacheEntryKind kind, const std::string& good, std::size_t at,
                     char mask)
      {
        std::string bad = good;
        bad[at] ^= mask;
        writeBytes (cache.entryPath ("view", kind), bad);
        return lookup (cache, kind);
      }

      fs::path dir_;
  };

  constexpr CacheEntryKind kKinds[] = {CacheEntryKind::MESHES, CacheEntryKind::TENSORS};

  const char*
  name (CacheEntryKind kind)
  {
    return kind == CacheEntryKind::MESHES ? "meshes" : "tensors";
  }
}

// ---- round trips ---------------------------------------------------------------------------------

TEST_F (TensorViewCacheTest, ViewRoundTripIsExact)
{
  const auto& pair = preparedPair ();
  const TensorViewCache cache = filledCache (1);
  const TensorView& saved = *pair.views[1];
  TensorView loaded;
  ASSERT_EQ (cache.loadView ("view", kKey, loaded), CacheEntryState::VALID);
  ASSERT_TRUE (loaded.scan);
  EXPECT_FALSE (loaded.tensors) << "tensors are an entry of their own";
  expectSameBits (saved.origin, loaded.origin, "origin");
  EXPECT_NE (saved.origin.norm (), 0.0) << "a view off the origin tests the origin";
  EXPECT_EQ (bits (saved.scan->resolution), bits (loaded.scan->resolution));
  EXPECT_EQ (bits (saved.scan->noise), bits (loaded.scan->noise));
  ASSERT_GT (saved.scan->reduced.polygons.size (), 500u);
  expectSameMesh (saved.scan->fine, loaded.scan->fine);
  expectSameMesh (saved.scan->reduced, loaded.scan->reduced);

  Eigen::Vector3d extents;
  ASSERT_EQ (cache.loadExtents ("view", kKey, extents), CacheEntryState::VALID);
  expectSameBits (pcl::principalExtents (*saved.scan->fine.cloud), extents, "extents");
}

TEST_F (TensorViewCacheTest, TensorRoundTripIsExact)
{
  const auto& pair = preparedPair ();
  const TensorViewCache cache = filledCache (0);
  Tensors::Ptr loaded;
  ASSERT_EQ (cache.loadTensors ("view", kKey, pair.dims, hashTensors (), loaded), CacheEntryState::VALID);
  ASSERT_TRUE (loaded);
  const Tensors& saved = *pair.views[0]->tensors;
  ASSERT_GT (saved.size (), 1000u);
  EXPECT_GT (pcl::computeTensorMemoryUsage (saved).non_zero_bins, saved.size ());
  expectSameTensors (saved, *loaded);
}

TEST_F (TensorViewCacheTest, CloudMetadataAndOddPolygonsSurvive)
{
  // What prepareTensorView does not set: a header, a sensor, an unorganized-but-2D shape, a quad.
  auto scan = std::make_shared<pcl::PreparedScan> (*preparedPair ().views[0]->scan);
  scan->reduced.cloud.reset (new pcl::PointCloud<pcl::PointNormal> (*scan->reduced.cloud));
  auto& cloud = *scan->reduced.cloud;
  cloud.header.frame_id = std::string ("frame\0with nul", 14);
  cloud.header.stamp = 123456789012345ull;
  cloud.header.seq = 77;
  cloud.sensor_origin_ = Eigen::Vector4f (1.f, -2.f, 3.5f, 0.f);
  cloud.sensor_orientation_ = Eigen::Quaternionf (0.5f, 0.5f, -0.5f, 0.5f);
  cloud.points.resize (cloud.size () / 2 * 2);
  cloud.width = static_cast<std::uint32_t> (cloud.size () / 2);
  cloud.height = 2;
  cloud.is_dense = false;
  scan->reduced.polygons.assign (3, pcl::Vertices ());
  scan->reduced.polygons[0].vertices = {0, 1, 2, 3};
  scan->reduced.viewpoint = pcl::ScanViewpoint::fromPositiveZ ();
  TensorView view;
  view.scan = scan;
  view.origin = Eigen::Vector3d (1e6, -0.0, 1.0 / 3.0);

  TensorViewCache cache ((dir_ / "cache").string ());
  cache.saveView ("odd", kKey, view);
  TensorView loaded;
  ASSERT_EQ (cache.loadView ("odd", kKey, loaded), CacheEntryState::VALID);
  expectSameMesh (scan->reduced, loaded.scan->reduced);
  expectSameBits (view.origin, loaded.origin, "origin");
}

// D from the cached extents alone is Eq. 1 over the views, bit for bit.
TEST_F (TensorViewCacheTest, DimensionsFromCachedExtentsAreEquationOne)
{
  const auto& pair = preparedPair ();
  TensorViewCache cache ((dir_ / "cache").string ());
  std::vector<Eigen::Vector3d> extents (2);
  for (int i = 0; i < 2; ++i)
  {
    const std::string id = "view" + std::to_string (i);
    cache.saveView (id, kKey, *pair.views[i]);
    ASSERT_EQ (cache.loadExtents (id, kKey, extents[i]), CacheEntryState::VALID);
  }
  expectSameBits (pair.dims.D, pcl::objectDimensionsFromExtents (extents).D, "D");
  EXPECT_THROW (pcl::objectDimensionsFromExtents ({}), pcl::InvalidScanException);
}

// What pcl_tensor_prepare does per view: a first run prepares and stores the meshes, returns them
// and their extents; a second keeps the entry and returns the same extents without meshes. Tensors
// computed from the cache's meshes are those of the view, and are kept the next time.
TEST_F (TensorViewCacheTest, CachedExtentsAndTensorsAreComputedOnceThenKept)
{
  const auto& pair = preparedPair ();
  const auto& scan = pair.rendered[0].view;
  TensorViewCache cache ((dir_ / "cache").string ());
  pcl::io::CachedViewReport first, second, third, fourth;
  Eigen::Vector3d computed, kept;
  const auto view = pcl::io::cachedExtents (cache, "view", kKey, *scan.cloud, scan.viewpoint, pair.params.preparation, computed, first);
  ASSERT_TRUE (view);
  EXPECT_EQ (first.meshes_found, CacheEntryState::MISSING);
  EXPECT_TRUE (first.meshes_computed);
  expectSameBits (pcl::principalExtents (*pair.views[0]->scan->fine.cloud), computed, "extents computed");
  EXPECT_FALSE (pcl::io::cachedExtents (cache, "view", kKey, *scan.cloud, scan.viewpoint, pair.params.preparation, kept, second));
  EXPECT_EQ (second.meshes_found, CacheEntryState::VALID);
  EXPECT_FALSE (second.meshes_computed);
  expectSameBits (computed, kept, "extents kept");

  // No view given: its meshes come from the cache.
  const auto tensors = pcl::io::cachedTensors (cache, "view", kKey, pair.dims, pair.params, nullptr, third);
  EXPECT_TRUE (third.tensors_computed);
  ASSERT_EQ (tensors->size (), pair.views[0]->tensors->size ());
  for (std::size_t i = 0; i < tensors->size (); ++i)
    ASSERT_EQ ((*tensors)[i].bin_area, (*pair.views[0]->tensors)[i].bin_area) << "tensor " << i;
  pcl::io::cachedTensors (cache, "view", kKey, pair.dims, pair.params, nullptr, fourth);
  EXPECT_EQ (fourth.tensors_found, CacheEntryState::VALID);
  EXPECT_FALSE (fourth.tensors_computed);

  // Tensors for another D with the meshes entry gone: an I/O error, never tensors of nothing.
  fs::remove_all (dir_ / "cache");
  TensorViewCache emptied ((dir_ / "cache").string ());
  pcl::ObjectDimensions other = pair.dims;
  other.D *= 1.5;
  pcl::io::CachedViewReport fifth;
  EXPECT_THROW (pcl::io::cachedTensors (emptied, "view", kKey, other, pair.params, nullptr, fifth), pcl::IOException);
}

// Registration on loaded views gives exactly the transform of the views it was saved from.
TEST_F (TensorViewCacheTest, LoadedViewsRegisterExactlyAsTheOriginals)
{
  const auto& pair = preparedPair ();
  TensorViewCache cache ((dir_ / "cache").string ());
  std::vector<TensorView::Ptr> loaded;
  for (int i = 0; i < 2; ++i)
  {
    const std::string id = "view" + std::to_string (i);
    cache.saveView (id, kKey, *pair.views[i]);
    cache.saveTensors (id, kKey, pair.dims, hashTensors (), *pair.views[i]->tensors);
    auto view = std::make_shared<TensorView> ();
    Tensors::Ptr tensors;
    ASSERT_EQ (cache.loadView (id, kKey, *view), CacheEntryState::VALID);
    ASSERT_EQ (cache.loadTensors (id, kKey, pair.dims, hashTensors (), tensors), CacheEntryState::VALID);
    view->tensors = tensors;
    view->dimensions = pair.dims;
    loaded.push_back (view);
  }
  const auto align = [&] (const TensorView::ConstPtr& model, const TensorView::ConstPtr& scene) {
    pcl::registration::TensorRegistration<pcl::PointXYZ> registration;
    registration.setTargetView (model);
    registration.setSourceView (scene);
    registration.setObjectDimensions (pair.dims);
    registration.setInputTarget (pair.rendered[0].view.cloud);
    registration.setInputSource (pair.rendered[1].view.cloud);
    registration.setTargetViewpoint (pair.rendered[0].view.viewpoint);
    registration.setSourceViewpoint (pair.rendered[1].view.viewpoint);
    pcl::PointCloud<pcl::PointXYZ> aligned;
    registration.align (aligned);
    EXPECT_TRUE (registration.hasConverged ());
    return std::make_pair (registration.getFinalTransformation (), registration.getReport ().hypotheses_tried);
  };
  const auto original = align (pair.views[0], pair.views[1]);
  const auto from_cache = align (loaded[0], loaded[1]);
  EXPECT_TRUE (original.first == from_cache.first) << original.first << "\n\n" << from_cache.first;
  EXPECT_EQ (original.second, from_cache.second);
  EXPECT_FALSE (original.first.isIdentity ());
}

// ---- states --------------------------------------------------------------------------------------

TEST_F (TensorViewCacheTest, EntriesNeverWrittenAreMissing)
{
  const TensorViewCache cache ((dir_ / "new" / "nested").string ());
  EXPECT_TRUE (fs::is_directory (dir_ / "new" / "nested")) << "the folder is created";
  for (const auto kind : kKinds)
    EXPECT_EQ (lookup (cache, kind), CacheEntryState::MISSING) << name (kind);
}

TEST_F (TensorViewCacheTest, AFlippedPayloadByteIsCorrupt)
{
  const TensorViewCache cache = filledCache ();
  for (const auto kind : kKinds)
  {
    const std::string path = cache.entryPath ("view", kind);
    const std::string good = readBytes (path);
    ASSERT_EQ (lookup (cache, kind), CacheEntryState::VALID) << name (kind);
    for (const std::size_t at : {std::size_t (40), good.size () / 2, good.size () - 9, good.size () - 1})
      EXPECT_EQ (lookupFlipped (cache, kind, good, at, 0x10), CacheEntryState::CORRUPT)
          << name (kind) << " byte " << at << " of " << good.size ();
    writeBytes (path, good);
    EXPECT_EQ (lookup (cache, kind), CacheEntryState::VALID) << name (kind);
  }
}

TEST_F (TensorViewCacheTest, AFlippedHeaderByteIsNeverValid)
{
  const TensorViewCache cache = filledCache ();
  for (const auto kind : kKinds)
  {
    const std::string path = cache.entryPath ("view", kind);
    const std::string good = readBytes (path);
    // The magic bytes, the kind and the key: the checksum (or the magic) tells.
    for (const std::size_t at : {0, 3, 7, 12, 15, 16, 23, 24, 31})
      EXPECT_EQ (lookupFlipped (cache, kind, good, at, 0x01), CacheEntryState::CORRUPT) << name (kind) << " byte " << at;
    // The payload size: longer than the file (a bit of its low or high bytes), or one byte shorter.
    std::uint64_t size;
    std::memcpy (&size, good.data () + 32, sizeof (size));
    ASSERT_EQ (size + 48, good.size ()) << "the layout documented in tensor_view_cache.h";
    for (const std::uint64_t bad_size :
         std::vector<std::uint64_t>{size + 1, size + 64, size | (1ull << 40), size | (1ull << 63), ~0ull, size - 1})
    {
      std::string bad = good;
      std::memcpy (&bad[32], &bad_size, sizeof (bad_size));
      writeBytes (path, bad);
      EXPECT_EQ (lookup (cache, kind), bad_size < size ? CacheEntryState::CORRUPT : CacheEntryState::TRUNCATED)
          << name (kind) << " payload size " << bad_size << " for " << size;
    }
  }
}

TEST_F (TensorViewCacheTest, ACutFileIsTruncated)
{
  const TensorViewCache cache = filledCache ();
  for (const auto kind : kKinds)
  {
    const std::string path = cache.entryPath ("view", kind);
    const std::string good = readBytes (path);
    // Inside the magic, the version, the key, the size; the header alone; inside the payload and checksum.
    for (const std::size_t size : {std::size_t (0), std::size_t (1), std::size_t (7), std::size_t (8), std::size_t (11),
                                   std::size_t (12), std::size_t (20), std::size_t (39), std::size_t (40),
                                   std::size_t (47), good.size () / 2, good.size () - 8, good.size () - 1})
    {
      writeBytes (path, good.substr (0, size));
      EXPECT_EQ (lookup (cache, kind), CacheEntryState::TRUNCATED) << name (kind) << " cut at " << size;
    }
    // One byte more is not a cut: it is not the file that was written.
    writeBytes (path, good + 'x');
    EXPECT_EQ (lookup (cache, kind), CacheEntryState::CORRUPT) << name (kind);
  }
}

TEST_F (TensorViewCacheTest, AnEmptyFileIsTruncated)
{
  const TensorViewCache cache ((dir_ / "cache").string ());
  for (const auto kind : kKinds)
  {
    writeBytes (cache.entryPath ("view", kind), "");
    EXPECT_EQ (lookup (cache, kind), CacheEntryState::TRUNCATED) << name (kind);
  }
}

TEST_F (TensorViewCacheTest, AnotherKeyDOrTensorSettingIsStale)
{
  const auto& pair = preparedPair ();
  const TensorViewCache cache = filledCache ();
  const TensorViewCacheKey other_source{kKey.source + 1, kKey.preparation};
  const TensorViewCacheKey other_preparation{kKey.source, kKey.preparation ^ (1ull << 63)};
  for (const auto& key : {other_source, other_preparation})
  {
    TensorView view;
    Eigen::Vector3d extents;
    Tensors::Ptr tensors;
    EXPECT_EQ (cache.loadView ("view", key, view), CacheEntryState::STALE);
    EXPECT_EQ (cache.loadExtents ("view", key, extents), CacheEntryState::STALE);
    EXPECT_EQ (cache.loadTensors ("view", key, pair.dims, hashTensors (), tensors), CacheEntryState::STALE);
    EXPECT_FALSE (view.scan);
    EXPECT_FALSE (tensors);
  }
  // Tensors of another D (one ulp off in one dimension) or other settings.
  Tensors::Ptr tensors;
  pcl::ObjectDimensions other_d = pair.dims;
  other_d.D.z () = std::nextafter (other_d.D.z (), 0.0);
  EXPECT_EQ (cache.loadTensors ("view", kKey, other_d, hashTensors (), tensors), CacheEntryState::STALE);
  auto other_params = pair.params;
  other_params.grid_size = 12;
  EXPECT_EQ (cache.loadTensors ("view", kKey, pair.dims, pcl::io::hashTensorParameters (other_params), tensors),
            CacheEntryState::STALE);
  EXPECT_FALSE (tensors);
  // The meshes do not depend on D: they stay valid; and meshes written again leave the tensors valid.
  EXPECT_EQ (lookup (cache, CacheEntryKind::MESHES), CacheEntryState::VALID);
  cache.saveView ("view", kKey, *pair.views[0]);
  EXPECT_EQ (lookup (cache, CacheEntryKind::TENSORS), CacheEntryState::VALID);
}

TEST_F (TensorViewCacheTest, AnotherVersionIsReportedAsSuch)
{
  const TensorViewCache cache = filledCache ();
  for (const auto kind : kKinds)
  {
    const std::string path = cache.entryPath ("view", kind);
    const std::string good = readBytes (path);
    std::uint32_t version;
    std::memcpy (&version, good.data () + 8, sizeof (version));
    ASSERT_EQ (version, pcl::io::TENSOR_VIEW_CACHE_VERSION) << "the layout documented in tensor_view_cache.h";
    for (const std::uint32_t other : {0u, pcl::io::TENSOR_VIEW_CACHE_VERSION + 1, 0xffffffffu})
    {
      std::string bad = good;
      std::memcpy (&bad[8], &other, sizeof (other));
      writeBytes (path, bad);
      EXPECT_EQ (lookup (cache, kind), CacheEntryState::OTHER_VERSION) << name (kind) << " version " << other;
    }
  }
}

TEST_F (TensorViewCacheTest, AnEntryOfTheOtherKindIsCorrupt)
{
  const TensorViewCache cache = filledCache ();
  const std::string meshes = readBytes (cache.entryPath ("view", CacheEntryKind::MESHES));
  const std::string tensors = readBytes (cache.entryPath ("view", CacheEntryKind::TENSORS));
  writeBytes (cache.entryPath ("view", CacheEntryKind::MESHES), tensors);
  writeBytes (cache.entryPath ("view", CacheEntryKind::TENSORS), meshes);
  for (const auto kind : kKinds)
    EXPECT_EQ (lookup (cache, kind), CacheEntryState::CORRUPT) << name (kind);
}

TEST_F (TensorViewCacheTest, AFolderInPlaceOfAnEntryIsCorrupt)
{
  const TensorViewCache cache ((dir_ / "cache").string ());
  for (const auto kind : kKinds)
  {
    fs::create_directories (cache.entryPath ("view", kind));
    EXPECT_EQ (lookup (cache, kind), CacheEntryState::CORRUPT) << name (kind);
    EXPECT_THROW (cache.saveView ("view", kKey, *preparedPair ().views[0]), pcl::IOException);
  }
}

// Random bytes, random bytes behind a valid header, and a valid frame (checksum and all) around a
// payload that does not decode: never VALID, never a crash or a huge allocation.
TEST_F (TensorViewCacheTest, GarbageIsNeverValid)
{
  const TensorViewCache cache = filledCache ();
  std::mt19937 rng (2006);
  std::uniform_int_distribution<int> byte (0, 255);
  const auto random_bytes = [&] (std::size_t n) {
    std::string s (n, '\0');
    for (auto& c : s)
      c = static_cast<char> (byte (rng));
    return s;
  };
  for (const auto kind : kKinds)
  {
    const std::string path = cache.entryPath ("view", kind);
    const std::string header = readBytes (path).substr (0, 40);
    for (const std::size_t n : {1, 8, 40, 47, 48, 100, 4096, 100000})
    {
      writeBytes (path, random_bytes (n));
      EXPECT_NE (lookup (cache, kind), CacheEntryState::VALID) << name (kind) << ", " << n << " random bytes";
      writeBytes (path, header.substr (0, 32) + random_bytes (n));
      EXPECT_NE (lookup (cache, kind), CacheEntryState::VALID) << name (kind) << ", a header and " << n << " random bytes";

      // Behind what must be right for the content to be decoded at all: D and the tensor hash, or a
      // sensor model.
      std::string payload;
      if (kind == CacheEntryKind::TENSORS)
      {
        const std::uint64_t tensor_hash = hashTensors ();
        payload.append (reinterpret_cast<const char*> (preparedPair ().dims.D.data ()), 3 * sizeof (double));
        payload.append (reinterpret_cast<const char*> (&tensor_hash), sizeof (tensor_hash));
      }
      else
        payload = random_bytes (64) + std::string (4, '\0');
      payload += random_bytes (n);
      std::string framed = header.substr (0, 32);
      const std::uint64_t size = payload.size ();
      framed.append (reinterpret_cast<const char*> (&size), sizeof (size));
      framed += payload;
      const std::uint64_t checksum = pcl::io::hashBytes (framed);
      framed.append (reinterpret_cast<const char*> (&checksum), sizeof (checksum));
      writeBytes (path, framed);
      // loadExtents() checks the frame and decodes the head alone, so only the full loads can tell.
      TensorView view;
      Tensors::Ptr tensors;
      const auto state = kind == CacheEntryKind::MESHES
                             ? cache.loadView ("view", kKey, view)
                             : cache.loadTensors ("view", kKey, preparedPair ().dims, hashTensors (), tensors);
      EXPECT_EQ (state, CacheEntryState::CORRUPT) << name (kind) << ", a framed payload of " << n << " random bytes";
      EXPECT_FALSE (view.scan || tensors);
    }
  }
}

// Two threads save one entry under two keys while a third reads it: every read finds a whole entry.
TEST_F (TensorViewCacheTest, ConcurrentWritersLeaveWholeEntries)
{
  const auto& pair = preparedPair ();
  const TensorViewCache cache ((dir_ / "cache").string ());
  Tensors few;
  few.points.assign (pair.views[0]->tensors->begin (), pair.views[0]->tensors->begin () + 200);
  few.width = 200;
  few.height = 1;
  const TensorViewCacheKey other{kKey.source, kKey.preparation + 1};
  std::atomic<bool> done{false};
  const auto writer = [&] (const TensorViewCacheKey& key) {
    for (int i = 0; i < 200; ++i)
      cache.saveTensors ("view", key, pair.dims, 7, few);
  };
  std::thread a (writer, kKey), b (writer, other);
  std::size_t reads = 0, valid = 0;
  std::thread reader ([&] {
    while (!done)
    {
      Tensors::Ptr loaded;
      const auto state = cache.loadTensors ("view", kKey, pair.dims, 7, loaded);
      ++reads;
      valid += state == CacheEntryState::VALID;
      if (state != CacheEntryState::VALID && state != CacheEntryState::STALE && state != CacheEntryState::MISSING)
        ADD_FAILURE () << "read " << pcl::io::toString (state);
      if (state == CacheEntryState::VALID)
      {
        ASSERT_EQ (loaded->size (), 200u);
      }
    }
  });
  a.join ();
  b.join ();
  done = true;
  reader.join ();
  EXPECT_GT (reads, 0u);
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator (dir_ / "cache"))
    files += entry.is_regular_file () ? 1 : 0;
  EXPECT_EQ (files, 1u) << "no temporary file is left behind";
}

TEST_F (TensorViewCacheTest, EntryPathsRefuseUnsafeIds)
{
  const TensorViewCache cache ((dir_ / "cache").string ());
  EXPECT_EQ (fs::path (cache.entryPath ("a-1_b.c", CacheEntryKind::MESHES)).filename ().string (), "a-1_b.c.meshes.tvc");
  EXPECT_EQ (fs::path (cache.entryPath ("a-1_b.c", CacheEntryKind::TENSORS)).filename ().string (), "a-1_b.c.tensors.tvc");
  EXPECT_EQ (fs::path (cache.entryPath ("x", CacheEntryKind::MESHES)).parent_path ().string (), (dir_ / "cache").string ());
  for (const std::string& id : std::vector<std::string>{"", "../x", "a/b", ".hidden", "a b", std::string (201, 'a')})
    EXPECT_THROW (cache.entryPath (id, CacheEntryKind::MESHES), pcl::BadArgumentException) << "'" << id << "'";
}

TEST_F (TensorViewCacheTest, ACacheFolderThatIsAFileIsRefused)
{
  writeBytes ((dir_ / "file").string (), "x");
  EXPECT_THROW (TensorViewCache ((dir_ / "file").string ()), pcl::IOException);
}

TEST (TensorViewCacheState, NamesEveryState)
{
  std::set<std::string> names;
  for (const auto s : {CacheEntryState::VALID, CacheEntryState::MISSING, CacheEntryState::CORRUPT,
                       CacheEntryState::TRUNCATED, CacheEntryState::STALE, CacheEntryState::OTHER_VERSION})
    names.insert (pcl::io::toString (s));
  EXPECT_EQ (names, (std::set<std::string>{"valid", "missing", "corrupt", "truncated", "stale", "other_version"}));
}

// ---- keys and hashes -------------------------------------------------------------------------------

TEST (TensorViewCacheKey, EveryPreparationFieldAndTheSensorChangeTheHash)
{
  const pcl::ScanPreparationParams base;
  const pcl::ScanViewpoint sensor = pcl::ScanViewpoint::lookingAt (Eigen::Vector3d (0, 0, 5), Eigen::Vector3d::Zero ());
  using P = pcl::ScanPreparationParams;
  const std::vector<std::pair<const char*, std::function<void (P&, pcl::ScanViewpoint&)>>> changes{
      {"edge_std_devs", [] (P& p, pcl::ScanViewpoint&) { p.edge_std_devs += 0.1; }},
      {"target_faces", [] (P& p, pcl::ScanViewpoint&) { p.target_faces += 1; }},
      {"normal_method", [] (P& p, pcl::ScanViewpoint&) { p.normal_method = pcl::ScanMeshNormalEstimation::Method::FACE_AVERAGE; }},
      {"normal_radius_resolutions", [] (P& p, pcl::ScanViewpoint&) { p.normal_radius_resolutions *= 2; }},
      {"stray_fragment_gap", [] (P& p, pcl::ScanViewpoint&) { p.stray_fragment_gap += 1; }},
      {"stray_fragment_fraction", [] (P& p, pcl::ScanViewpoint&) { p.stray_fragment_fraction = 0; }},
      {"speck_max_pixels", [] (P& p, pcl::ScanViewpoint&) { p.speck_max_pixels += 1; }},
      {"speck_jump", [] (P& p, pcl::ScanViewpoint&) { p.speck_jump *= 2; }},
      {"reduction_grid_step", [] (P& p, pcl::ScanViewpoint&) { p.reduction_grid_step = 2; }},
      {"sensor model", [] (P&, pcl::ScanViewpoint& v) { v.model = pcl::ScanViewpoint::Model::orthographic; }},
      {"sensor position", [] (P&, pcl::ScanViewpoint& v) { v.sensor_pose.translation ().x () += 1e-9; }},
      {"sensor rotation", [] (P&, pcl::ScanViewpoint& v) { v.sensor_pose.linear () (0, 1) = -0.0; }}};
  std::set<std::uint64_t> hashes{pcl::io::hashPreparation (base, sensor)};
  EXPECT_EQ (pcl::io::hashPreparation (base, sensor), pcl::io::hashPreparation (P (), sensor)) << "deterministic";
  for (const auto& [field, change] : changes)
  {
    P p = base;
    pcl::ScanViewpoint v = sensor;
    change (p, v);
    EXPECT_TRUE (hashes.insert (pcl::io::hashPreparation (p, v)).second) << field << " does not change the hash";
  }
}

TEST (TensorViewCacheKey, TheTensorHashTakesTheTensorSettingsOnly)
{
  using P = pcl::registration::TensorRegistrationParams;
  const P base;
  std::set<std::uint64_t> hashes{pcl::io::hashTensorParameters (base)};
  const std::vector<std::pair<const char*, std::function<void (P&)>>> changes{
      {"grid_size", [] (P& p) { p.grid_size = 12; }},
      {"partners_per_vertex", [] (P& p) { p.partners_per_vertex = 4; }},
      {"min_normal_angle", [] (P& p) { p.min_normal_angle = 6.0; }},
      {"region_growing", [] (P& p) { p.region_growing = !p.region_growing; }}};
  for (const auto& [field, change] : changes)
  {
    P p = base;
    change (p);
    EXPECT_TRUE (hashes.insert (pcl::io::hashTensorParameters (p)).second) << field << " does not change the hash";
  }
  // Matching, verification and meshing settings leave the tensors as they are (meshing is in the key).
  P other = base;
  other.overlap_threshold = 0.7f;
  other.correlation_threshold = 0.6f;
  other.max_hypotheses = 1;
  other.verification.correspondence_fraction *= 2;
  other.preparation.target_faces = 500;
  EXPECT_EQ (pcl::io::hashTensorParameters (other), pcl::io::hashTensorParameters (base));
}

TEST (TensorViewCacheKey, EveryFlippedBitChangesTheContentHash)
{
  std::mt19937 rng (7);
  for (std::size_t n = 0; n <= 40; ++n)
  {
    std::string bytes (n, '\0');
    for (auto& c : bytes)
      c = static_cast<char> (rng ());
    const std::uint64_t h = pcl::io::hashBytes (bytes);
    for (std::size_t i = 0; i < n; ++i)
      for (int bit = 0; bit < 8; ++bit)
      {
        std::string flipped = bytes;
        flipped[i] ^= static_cast<char> (1 << bit);
        ASSERT_NE (pcl::io::hashBytes (flipped), h) << n << " bytes, byte " << i << " bit " << bit;
      }
    EXPECT_NE (pcl::io::hashBytes (bytes + '\0'), h) << "a trailing zero counts";
  }
}

TEST (TensorViewCacheKey, TheContentHashIgnoresHowBytesAreSplit)
{
  const std::string bytes = "the quick brown fox jumps over the lazy dog, twice: the quick brown fox";
  for (std::size_t a = 0; a <= bytes.size (); a += 3)
    for (std::size_t b = a; b <= bytes.size (); b += 5)
    {
      pcl::io::ContentHash h;
      h.update (bytes.substr (0, a)).update (bytes.substr (a, b - a)).update (bytes.substr (b));
      ASSERT_EQ (h.digest (), pcl::io::hashBytes (bytes)) << a << ", " << b;
    }
  EXPECT_EQ (pcl::io::toHex (0x0123456789abcdefull), "0123456789abcdef");
  EXPECT_EQ (pcl::io::toHex (pcl::io::hashBytes ("")).size (), 16u);
}

TEST (TensorViewCacheKey, FileHashesFollowTheBytes)
{
  const std::string bytes = std::string (100000, 'a') + std::string ("\0\x01\x02", 3) + "tail";
  const std::string a = pcl_tensor_test::writeTempFile ("hash_a.bin", bytes);
  const std::string b = pcl_tensor_test::writeTempFile ("hash_b.bin", bytes);
  std::string flipped = bytes;
  flipped[70000] ^= 0x04;
  const std::string c = pcl_tensor_test::writeTempFile ("hash_c.bin", flipped);
  EXPECT_EQ (pcl::io::hashFileContents (a), pcl::io::hashFileContents (b));
  EXPECT_EQ (pcl::io::hashFileContents (a), pcl::io::hashBytes (bytes));
  EXPECT_NE (pcl::io::hashFileContents (a), pcl::io::hashFileContents (c));
  EXPECT_THROW (pcl::io::hashFileContents ("/nonexistent/file.ply"), pcl::IOException);
  EXPECT_THROW (pcl::io::hashFileContents (::testing::TempDir ()), pcl::IOException);
  for (const auto& f : {a, b, c})
    std::remove (f.c_str ());
}

TEST (TensorViewCacheKey, CloudHashesTakeOrganizationAndEveryCoordinate)
{
  pcl::PointCloud<pcl::PointXYZ> cloud = pcl_tensor_test::makeHeightField (3, 10, 12, 0.01, 0.1);
  const std::uint64_t h = pcl::io::hashPointCloud (cloud);
  EXPECT_EQ (pcl::io::hashPointCloud (pcl::PointCloud<pcl::PointXYZ> (cloud)), h);
  pcl::PointCloud<pcl::PointXYZ> reshaped = cloud;
  reshaped.width = 12 * 10 / 5;
  reshaped.height = 5;
  EXPECT_NE (pcl::io::hashPointCloud (reshaped), h) << "same points, other grid";
  std::set<std::uint64_t> hashes{h};
  for (int k = 0; k < 3; ++k)
  {
    pcl::PointCloud<pcl::PointXYZ> moved = cloud;
    moved[cloud.size () - 1].data[k] = 0.5f;
    EXPECT_TRUE (hashes.insert (pcl::io::hashPointCloud (moved)).second) << "coordinate " << k;
  }
}

TEST (TensorViewCacheKey, ViewIdsTellFoldersApartAndAreFileNameSafe)
{
  const fs::path root = fs::path (::testing::TempDir ()) / ("view_ids_" + std::to_string (::getpid ()));
  fs::create_directories (root / "a");
  fs::create_directories (root / "b");
  const std::string in_a = pcl::io::viewIdOf ((root / "a" / "scan.ply").string ());
  const std::string in_b = pcl::io::viewIdOf ((root / "b" / "scan.ply").string ());
  EXPECT_NE (in_a, in_b);
  EXPECT_EQ (in_a.rfind ("scan-", 0), 0u) << in_a;
  EXPECT_EQ (in_a.size (), std::string ("scan-").size () + 16);
  EXPECT_EQ (pcl::io::viewIdOf ((root / "b" / ".." / "a" / "scan.ply").string ()), in_a) << "one file, two spellings";
  EXPECT_EQ (pcl::io::viewIdOf ((root / "a" / "scan.pcd").string ()).substr (0, 5), "scan-");
  EXPECT_NE (pcl::io::viewIdOf ((root / "a" / "scan.pcd").string ()), in_a) << "another file";
  for (const std::string& path : std::vector<std::string>{"a b/\"q\" é.ply", ".hidden.ply", "../up.ply", std::string (300, 'x') + ".ply"})
  {
    const std::string id = pcl::io::viewIdOf (path);
    EXPECT_TRUE (pcl::io::isValidViewId (id)) << "'" << id << "' from '" << path << "'";
  }
  fs::remove_all (root);
}

// ---- atomic writes -------------------------------------------------------------------------------

TEST_F (TensorViewCacheTest, AWriterNotCommittedLeavesTheDestinationAndNoTemporary)
{
  const std::string destination = (dir_ / "model.ply").string ();
  writeBytes (destination, "old");
  std::string temporary;
  {
    pcl::io::AtomicFileWriter writer (destination);
    temporary = writer.temporaryPath ();
    EXPECT_EQ (fs::path (temporary).parent_path ().string (), dir_.string ()) << "the temporary lives beside the destination";
    EXPECT_EQ (fs::path (temporary).extension ().string (), ".ply") << "format-by-extension writers see the destination's";
    EXPECT_NE (temporary, destination);
    writeBytes (temporary, "new, half written");
    EXPECT_FALSE (writer.committed ());
  }
  EXPECT_EQ (readBytes (destination), "old");
  EXPECT_FALSE (fs::exists (temporary));
  EXPECT_EQ (std::distance (fs::directory_iterator (dir_), fs::directory_iterator ()), 1);
}

TEST_F (TensorViewCacheTest, ACommitReplacesTheDestination)
{
  const std::string destination = (dir_ / "poses.conf").string ();
  writeBytes (destination, "old");
  pcl::io::AtomicFileWriter writer (destination);
  writeBytes (writer.temporaryPath (), "new");
  EXPECT_EQ (readBytes (destination), "old") << "nothing changes before the commit";
  writer.commit ();
  EXPECT_TRUE (writer.committed ());
  EXPECT_EQ (readBytes (destination), "new");
  EXPECT_FALSE (fs::exists (writer.temporaryPath ()));
  EXPECT_THROW (writer.commit (), pcl::IOException) << "twice";

  const std::string bytes ("with\0nul\xff", 9);
  pcl::io::writeFileAtomically (destination, bytes);
  EXPECT_EQ (readBytes (destination), bytes);
  EXPECT_EQ (std::distance (fs::directory_iterator (dir_), fs::directory_iterator ()), 1);
}

TEST_F (TensorViewCacheTest, AtomicWritersRefuseWhatTheyCannotWrite)
{
  const std::string destination = (dir_ / "x.bin").string ();
  writeBytes (destination, "old");
  {
    pcl::io::AtomicFileWriter nothing_written (destination);
    EXPECT_THROW (nothing_written.commit (), pcl::IOException);
  }
  EXPECT_EQ (readBytes (destination), "old");
  EXPECT_THROW (pcl::io::AtomicFileWriter ((dir_ / "missing" / "x.bin").string ()), pcl::IOException);
  EXPECT_THROW (pcl::io::AtomicFileWriter (dir_.string ()), pcl::IOException);
  EXPECT_THROW (pcl::io::writeFileAtomically ((dir_ / "missing" / "x.bin").string (), "x"), pcl::IOException);
  pcl::io::AtomicFileWriter one (destination), two (destination);
  EXPECT_NE (one.temporaryPath (), two.temporaryPath ()) << "two writers of one file never share a temporary";
}

// ---- pair registrations and cached multiview inputs ----------------------------------------------

TEST_F (TensorViewCacheTest, PairRoundTripIsExactAndKeyedByEverySetting)
{
  const auto& pair = preparedPair ();
  const TensorViewCache cache ((dir_ / "cache").string ());
  const auto report = pcl::registration::registerTensorViews (pair.views[0], pair.views[1], pair.dims, pair.params);
  ASSERT_TRUE (report.registered);
  const TensorViewCacheKey other{kKey.source + 1, kKey.preparation};
  const TensorViewCacheKey key = pcl::io::pairCacheKey (kKey, other, pair.dims, pair.params);
  cache.savePair ("a", "b", key, report);

  pcl::registration::TensorRegistrationReport loaded;
  ASSERT_EQ (cache.loadPair ("a", "b", key, loaded), CacheEntryState::VALID);
  EXPECT_TRUE (loaded.registered);
  EXPECT_EQ (std::memcmp (loaded.transform.data (), report.transform.data (), sizeof (float) * 16), 0);
  EXPECT_EQ (loaded.hypotheses_tried, report.hypotheses_tried);
  EXPECT_EQ (loaded.matches, report.matches);
  EXPECT_EQ (loaded.failures, report.failures);
  EXPECT_EQ (bits (loaded.verification.fine_correspondences), bits (report.verification.fine_correspondences));
  EXPECT_EQ (loaded.verification.stage, report.verification.stage);
  EXPECT_EQ (cache.loadPair ("b", "a", key, loaded), CacheEntryState::MISSING) << "a pair has a direction";

  // Any setting of the search, D or either view makes another key: the entry is stale, not reused.
  auto fewer = pair.params;
  fewer.max_hypotheses = 20;
  pcl::ObjectDimensions bigger = pair.dims;
  bigger.D *= 1.01;
  for (const TensorViewCacheKey& changed : {pcl::io::pairCacheKey (kKey, other, pair.dims, fewer),
                                            pcl::io::pairCacheKey (kKey, other, bigger, pair.params),
                                            pcl::io::pairCacheKey (other, kKey, pair.dims, pair.params)})
    EXPECT_EQ (cache.loadPair ("a", "b", changed, loaded), CacheEntryState::STALE);
}

TEST_F (TensorViewCacheTest, CachedViewsRegisterAsTheFirstRunDid)
{
  // Three views of a ring written as files: a first run fills the cache, a second takes every
  // meshes, tensors and pair entry from it and must give the same poses bit for bit.
  std::vector<pcl::SyntheticView> rendered;
  const std::vector<pcl::registration::MultiviewInput> files = ringFiles (rendered);
  const TensorViewCache cache ((dir_ / "cache").string ());
  const pcl::registration::MultiviewRegistrationParams params;
  std::vector<pcl::registration::MultiviewRegistrationResult> results;
  for (int run = 0; run < 2; ++run)
  {
    std::vector<pcl::registration::MultiviewInput> inputs;
    const auto reports = pcl::io::prepareMultiviewInputs (files.size (), [&] (std::size_t i) { return files[i]; }, params, 2,
                                                          &cache, inputs);
    for (const auto& r : reports)
    {
      EXPECT_EQ (r.meshes_computed, run == 0);
      EXPECT_EQ (r.tensors_computed, run == 0);
      EXPECT_EQ (r.meshes_found, run == 0 ? CacheEntryState::MISSING : CacheEntryState::VALID);
    }
    for (const auto& in : inputs)
      EXPECT_TRUE (in.view && in.view->tensors && !in.cloud) << in.name << ": the prepared view replaces the cloud";
    pcl::registration::MultiviewTensorRegistration registration;
    registration.setPairRegistration (pcl::io::cachedPairRegistration (cache, reports));
    results.push_back (registration.compute (inputs));
  }
  ASSERT_EQ (results[0].registeredCount (), 3u);
  ASSERT_EQ (results[1].registeredCount (), 3u);
  for (std::size_t i = 0; i < 3; ++i)
  {
    EXPECT_TRUE (results[0].views[i].pose.matrix () == results[1].views[i].pose.matrix ()) << i;
    const auto truth = rendered[0].view.pose.inverse () * rendered[i].view.pose;
    const auto error = pcl::registrationError (results[0].views[i].pose, truth, results[0].resolution);
    EXPECT_LT (error.rotation_deg, 0.5) << i;
  }
  EXPECT_EQ (std::distance (fs::directory_iterator (dir_ / "cache"), fs::directory_iterator ()),
             static_cast<std::ptrdiff_t> (3 * 2 + results[0].attempts.size ()))
      << "one meshes and one tensors entry per view, one entry per pair registered";
}

// A view whose sensor an earlier read kept, and whose meshes are cached under the key that sensor gives,
// is not loaded again: the loader is not called, and the run gives the same poses.
TEST_F (TensorViewCacheTest, ViewsOfAKnownSensorAreNotReadAgain)
{
  std::vector<pcl::SyntheticView> rendered;
  const std::vector<pcl::registration::MultiviewInput> files = ringFiles (rendered);
  const TensorViewCache cache ((dir_ / "cache").string ());
  const auto sensorKey = [&] (std::size_t i) { return pcl::io::scanSensorKey (pcl::io::hashFileContents (files[i].name), ""); };
  std::atomic<int> loads{0};
  const pcl::io::MultiviewInputLoader load = [&] (std::size_t i) {
    ++loads;
    pcl::io::saveScanSensor (cache, pcl::io::viewIdOf (files[i].name), sensorKey (i), files[i].viewpoint);
    return files[i];
  };
  pcl::ScanViewpoint shifted = files[1].viewpoint;
  shifted.sensor_pose.translation ().x () += 0.01;
  const auto lookup = [&] (bool wrong_sensor) -> pcl::io::MultiviewInputLookup {
    return [&, wrong_sensor] (std::size_t i, pcl::registration::MultiviewInput& input) {
      input.name = files[i].name;
      if (wrong_sensor && i == 1)
        return (input.viewpoint = shifted, true);
      return pcl::io::loadScanSensor (cache, pcl::io::viewIdOf (files[i].name), sensorKey (i), input.viewpoint);
    };
  };
  const pcl::registration::MultiviewRegistrationParams params;
  std::vector<pcl::registration::MultiviewRegistrationResult> results;
  for (int run = 0; run < 3; ++run)
  {
    loads = 0;
    std::vector<pcl::registration::MultiviewInput> inputs;
    const auto reports = pcl::io::prepareMultiviewInputs (files.size (), load, params, 2, &cache, inputs, {}, lookup (run == 2));
    EXPECT_EQ (loads, run == 0 ? 3 : run == 1 ? 0 : 1) << "run " << run;
    for (std::size_t i = 0; i < reports.size (); ++i)
      EXPECT_EQ (reports[i].scan_not_read, run == 1 || (run == 2 && i != 1)) << "run " << run << ", view " << i;
    results.push_back (pcl::registration::MultiviewTensorRegistration ().compute (inputs));
  }
  ASSERT_EQ (results[0].registeredCount (), 3u);
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_TRUE (results[0].views[i].pose.matrix () == results[1].views[i].pose.matrix ()) << i;

  // The entry itself: back exactly under its key, never under another.
  pcl::ScanViewpoint kept;
  ASSERT_TRUE (pcl::io::loadScanSensor (cache, pcl::io::viewIdOf (files[2].name), sensorKey (2), kept));
  EXPECT_TRUE (kept.sensor_pose.matrix () == files[2].viewpoint.sensor_pose.matrix ());
  EXPECT_EQ (kept.model, files[2].viewpoint.model);
  EXPECT_FALSE (pcl::io::loadScanSensor (cache, pcl::io::viewIdOf (files[2].name),
                                         pcl::io::scanSensorKey (sensorKey (2).source, "0,0,0"), kept))
      << "another --viewpoint";
  EXPECT_FALSE (pcl::io::loadScanSensor (cache, pcl::io::viewIdOf (files[2].name), sensorKey (1), kept)) << "another file";
}
