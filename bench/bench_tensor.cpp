/*
 * Throughput of pcl::TensorEstimation (Mian et al. 2006, Section 2) on one core.
 *
 * BM_TensorsBunny: all ten Stanford bunny scans, loaded, prepared with pcl::prepareScan (reduced
 * meshes of ~400 faces with normals) and D from all views (Eq. 1); one iteration computes the tensors
 * of all ten. Skipped when ../shared/data is absent.
 * BM_TensorEstimation: data the project makes itself: the part of the example object (icosahedron
 * subdivided 3 times, 1280 faces) that faces +z, the 400 faces with the largest normal z component,
 * an open patch as a range scan would see it, with the object's D.
 *
 * Counters: tensors/s (items_per_second), tensors per mesh, non-zero bins per tensor, bytes per
 * tensor stored sparsely and densely. Run with --benchmark_repetitions=5 and read the medians.
 */
#include <pcl/features/tensor.h>
#include <pcl/io/range_scan_io.h>
#include <pcl/simulation/example_object.h>
#include <pcl/surface/scan_preparation.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <fstream>
#include <numeric>

namespace
{
  struct BenchMesh
  {
    pcl::ScanMesh mesh;
    pcl::ObjectDimensions dims;
  };

  /** The 400 faces of the coarse example object that face +z most, re-indexed. */
  const BenchMesh&
  scanLikePatch ()
  {
    static const BenchMesh patch = []
    {
      pcl::ExampleObjectParams params;
      params.subdivisions = 3;
      const pcl::ScanMesh object = pcl::makeExampleObject (params);
      const auto& c = *object.cloud;
      std::vector<std::pair<float, std::size_t>> by_nz;
      for (std::size_t f = 0; f < object.polygons.size (); ++f)
      {
        const auto& v = object.polygons[f].vertices;
        const Eigen::Vector3f n = (c[v[1]].getVector3fMap () - c[v[0]].getVector3fMap ())
                                    .cross (c[v[2]].getVector3fMap () - c[v[0]].getVector3fMap ());
        by_nz.emplace_back (-n.normalized ().z (), f);
      }
      std::sort (by_nz.begin (), by_nz.end ());
      BenchMesh out;
      std::vector<int> remap (c.size (), -1);
      for (std::size_t k = 0; k < 400; ++k)
      {
        pcl::Vertices tri;
        for (const auto v : object.polygons[by_nz[k].second].vertices)
        {
          if (remap[v] < 0)
          {
            remap[v] = static_cast<int> (out.mesh.cloud->size ());
            out.mesh.cloud->push_back (c[v]);
          }
          tri.vertices.push_back (remap[v]);
        }
        out.mesh.polygons.push_back (tri);
      }
      out.dims.D = Eigen::Vector3d (0.2, 0.144, 0.11);
      return out;
    } ();
    return patch;
  }

  /** The ten reduced Stanford bunny scans (prepareScan defaults: ~400 faces), D from all raw views
    * (Eq. 1); empty when ../shared/data is absent. */
  const std::vector<BenchMesh>&
  bunnyScans ()
  {
    static const std::vector<BenchMesh> scans = []
    {
      std::vector<BenchMesh> out;
      const char* names[] = {"bun000", "bun045", "bun090", "bun180", "bun270", "bun315", "chin", "ear_back",
                             "top2", "top3"};
      std::vector<pcl::io::RangeScan> raw;
      for (const char* name : names)
      {
        const std::string path = std::string (PCL_TENSOR_SHARED_DATA) + "/stanford/bunny/" + name + ".ply";
        if (!std::ifstream (path).good ())
          return out;
        raw.push_back (pcl::io::loadRangeScan (path));
      }
      std::vector<const pcl::PointCloud<pcl::PointXYZ>*> views;
      for (const auto& r : raw)
        views.push_back (r.cloud.get ());
      const pcl::ObjectDimensions dims = pcl::computeObjectDimensions<pcl::PointXYZ> (views);
      for (const auto& r : raw)
      {
        BenchMesh m;
        m.mesh = pcl::prepareScan (*r.cloud, r.viewpoint).reduced;
        m.dims = dims;
        out.push_back (m);
      }
      return out;
    } ();
    return scans;
  }

  /** Face visiting of the benchmark: 0 brute force, 1 region growing (defaults), 2 the paper's region
    * growing (single seed, no guard band). */
  void
  configure (pcl::TensorEstimation<pcl::PointNormal, pcl::PointNormal, pcl::TensorDescriptor>& est, int mode)
  {
    est.setRegionGrowing (mode != 0);
    if (mode == 2)
    {
      est.setSeedEveryComponent (false);
      est.setGrowthMargin (0.0);
    }
  }

  void
  BM_TensorsBunny (benchmark::State& state)
  {
    const auto& scans = bunnyScans ();
    if (scans.empty ())
    {
      state.SkipWithError ("../shared/data/stanford/bunny is absent");
      return;
    }
    pcl::TensorEstimation<pcl::PointNormal, pcl::PointNormal, pcl::TensorDescriptor> est;
    est.setGridSize (static_cast<int> (state.range (0)));
    configure (est, static_cast<int> (state.range (1)));
    std::vector<pcl::PointCloud<pcl::TensorDescriptor>> out (scans.size ());
    std::size_t tensors = 0, visited = 0, clipped = 0;
    for (auto _ : state)
      for (std::size_t v = 0; v < scans.size (); ++v)
      {
        est.setInputCloud (scans[v].mesh.cloud);
        est.setInputNormals (scans[v].mesh.cloud);
        est.setPolygons (scans[v].mesh.polygons);
        est.setObjectDimensions (scans[v].dims);
        est.computeOrThrow (out[v]);
        tensors += out[v].size ();
        visited += est.getFacesVisited ();
        clipped += est.getFacesClipped ();
      }
    state.counters["faces_visited"] = static_cast<double> (visited) / static_cast<double> (tensors);
    state.counters["faces_clipped"] = static_cast<double> (clipped) / static_cast<double> (tensors);
    pcl::PointCloud<pcl::TensorDescriptor> all;
    std::size_t faces = 0;
    for (std::size_t v = 0; v < scans.size (); ++v)
    {
      all += out[v];
      faces += scans[v].mesh.polygons.size ();
    }
    const pcl::TensorMemoryUsage m = pcl::computeTensorMemoryUsage (all);
    state.SetItemsProcessed (static_cast<int64_t> (tensors));
    state.counters["faces_per_scan"] = static_cast<double> (faces) / scans.size ();
    state.counters["tensors_per_scan"] = static_cast<double> (all.size ()) / scans.size ();
    state.counters["nonzero_bins"] = static_cast<double> (m.non_zero_bins) / m.tensors;
    state.counters["sparse_B"] = static_cast<double> (m.sparse_bytes) / m.tensors;
    state.counters["dense_B"] = static_cast<double> (m.dense_bytes) / m.tensors;
    state.counters["sparse_payload_B"] = static_cast<double> (m.sparse_bin_bytes) / m.tensors;
    state.counters["dense_payload_B"] = static_cast<double> (m.dense_bin_bytes) / m.tensors;
    state.counters["saved_pct"] = 100.0 * m.savedFraction ();
  }

  void
  BM_TensorEstimation (benchmark::State& state)
  {
    const BenchMesh& in = scanLikePatch ();
    pcl::TensorEstimation<pcl::PointNormal, pcl::PointNormal, pcl::TensorDescriptor> est;
    est.setInputCloud (in.mesh.cloud);
    est.setInputNormals (in.mesh.cloud);
    est.setPolygons (in.mesh.polygons);
    est.setObjectDimensions (in.dims);
    est.setGridSize (static_cast<int> (state.range (0)));
    configure (est, static_cast<int> (state.range (1)));
    pcl::PointCloud<pcl::TensorDescriptor> out;
    std::size_t tensors = 0;
    for (auto _ : state)
    {
      est.computeOrThrow (out);
      tensors += out.size ();
      benchmark::DoNotOptimize (out.data ());
    }
    const pcl::TensorMemoryUsage m = pcl::computeTensorMemoryUsage (out);
    state.SetItemsProcessed (static_cast<int64_t> (tensors));
    state.counters["vertices"] = static_cast<double> (in.mesh.cloud->size ());
    state.counters["faces"] = static_cast<double> (in.mesh.polygons.size ());
    state.counters["tensors"] = static_cast<double> (out.size ());
    state.counters["nonzero_bins"] = static_cast<double> (m.non_zero_bins) / m.tensors;
    state.counters["sparse_B"] = static_cast<double> (m.sparse_bytes) / m.tensors;
    state.counters["dense_B"] = static_cast<double> (m.dense_bytes) / m.tensors;
    state.counters["saved_pct"] = 100.0 * m.savedFraction ();
  }
}

// Arguments: grid size N; face visiting: 0 brute force, 1 region growing (defaults), 2 paper's region growing.
BENCHMARK (BM_TensorsBunny)->ArgNames ({"N", "visit"})->ArgsProduct ({{10, 15}, {0, 1, 2}})
  ->Unit (benchmark::kMillisecond);
BENCHMARK (BM_TensorEstimation)->ArgNames ({"N", "visit"})->ArgsProduct ({{10, 15}, {0, 1, 2}})
  ->Unit (benchmark::kMillisecond);

BENCHMARK_MAIN ();
