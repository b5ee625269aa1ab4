/*
 * pcl_tensor: time to render the paper's 26 synthetic views (Section 6) at 400x400.
 *
 * Run: bench_render_views --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
 */
#include <pcl/io/scan_mesh_io.h>
#include <pcl/simulation/example_object.h>
#include <pcl/simulation/view_set.h>
#include <pcl/simulation/zbuffer_range_renderer.h>

#include <benchmark/benchmark.h>

#include <fstream>

namespace
{
  /** Render all 26 views of \a mesh per iteration; counters give points and triangles. */
  void
  render26 (benchmark::State& state, const pcl::ScanMesh& mesh)
  {
    pcl::RangeCameraParams camera;
    camera.width = camera.height = 400;
    pcl::ZBufferRangeRenderer renderer;
    renderer.setMesh (mesh);
    renderer.setCameraParams (camera);
    const auto target = pcl::boundingTarget (mesh);
    const auto poses = pcl::lookAtPoses (pcl::makeDefaultViewDirections (), target,
                                         pcl::fittingDistance (target, camera));
    std::size_t points = 0;
    for (auto _ : state)
    {
      points = 0;
      for (const auto& pose : poses)
      {
        const auto view = renderer.render (pose);
        for (const auto& p : *view.cloud)
          points += std::isfinite (p.z) ? 1 : 0;
      }
      benchmark::DoNotOptimize (points);
    }
    state.counters["triangles"] = static_cast<double> (mesh.polygons.size ());
    state.counters["points_per_view"] = static_cast<double> (points) / poses.size ();
    state.counters["views_per_s"] = benchmark::Counter (static_cast<double> (poses.size ()),
                                                        benchmark::Counter::kIsIterationInvariantRate);
  }

  void
  BM_Render26Views_ExampleObject (benchmark::State& state)
  {
    static const pcl::ScanMesh mesh = pcl::makeExampleObject ();
    render26 (state, mesh);
  }

  void
  BM_Render26Views_BunZipper (benchmark::State& state)
  {
    const std::string path = std::string (PCL_TENSOR_SHARED_DATA) + "/stanford/bunny/bun_zipper.ply";
    if (!std::ifstream (path).good ())
    {
      state.SkipWithError ("SKIPPED: ../shared/data/stanford/bunny/bun_zipper.ply is absent (third-party data)");
      for (auto _ : state)
      {
      }
      return;
    }
    static const pcl::ScanMesh mesh = pcl::io::loadScanMesh (path);
    render26 (state, mesh);
  }
}

BENCHMARK (BM_Render26Views_ExampleObject)->Unit (benchmark::kMillisecond)->UseRealTime ();
BENCHMARK (BM_Render26Views_BunZipper)->Unit (benchmark::kMillisecond)->UseRealTime ();
BENCHMARK_MAIN ();
