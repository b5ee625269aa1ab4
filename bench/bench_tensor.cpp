/*
 * Throughput of pcl::TensorEstimation (Mian et al. 2006, Section 2) on one core.
 *
 * Input: a scan-like reduced mesh of ~400 faces. Until pcl::prepareScan lands, it is the part of the
 * example object (icosahedron subdivided 3 times, 1280 faces) that faces +z: the 400 faces with the
 * largest normal z component, an open patch as a range scan would see it, with the object's D.
 *
 * Counters: tensors/s (items_per_second), tensors per mesh, non-zero bins per tensor, bytes per
 * tensor stored sparsely and densely. Run with --benchmark_repetitions=5 and read the medians.
 */
#include <pcl/features/tensor.h>
#include <pcl/simulation/example_object.h>

#include <benchmark/benchmark.h>

#include <algorithm>
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
    est.setRegionGrowing (state.range (1) != 0);
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

// Arguments: grid size N, region growing (1) or brute force (0).
BENCHMARK (BM_TensorEstimation)->ArgNames ({"N", "rg"})->Args ({10, 1})->Args ({10, 0})->Args ({15, 1})->Args ({15, 0})
  ->Unit (benchmark::kMillisecond);

BENCHMARK_MAIN ();
