/*
 * pcl_tensor: time one range scan from loaded cloud to reduced mesh with normals (issue: foundation).
 *
 *   bench_scan_preparation --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
 *
 * Runs on the built-in example object always, and on the Stanford bunny scan bun000 when
 * ../shared/data is present. File reading is timed separately from preparation.
 */
#include <pcl/io/ply_io.h>
#include <pcl/io/range_scan_io.h>
#include <pcl/simulation/example_object.h>
#include <pcl/surface/quadric_mesh_reduction.h>
#include <pcl/surface/range_scan_triangulation.h>
#include <pcl/surface/scan_preparation.h>

#include <benchmark/benchmark.h>

#include <fstream>

namespace
{
  const std::string kBunny = std::string (PCL_TENSOR_SHARED_DATA) + "/stanford/bunny/bun000.ply";

  bool
  haveBunny (benchmark::State& state)
  {
    if (std::ifstream (kBunny).good ())
      return true;
    state.SkipWithError ("../shared/data/stanford/bunny/bun000.ply is absent");
    return false;
  }

  const pcl::io::RangeScan&
  bunny ()
  {
    static const pcl::io::RangeScan scan = pcl::io::loadRangeScan (kBunny);
    return scan;
  }

  void
  BM_ReadBunnyScan (benchmark::State& state)
  {
    if (!haveBunny (state))
      return;
    for (auto _ : state)
      benchmark::DoNotOptimize (pcl::io::loadRangeScan (kBunny));
  }

  /** The peer: PCL's own PLY reader on the same file (the ratio to BM_ReadBunnyScan is the gain). */
  void
  BM_ReadBunnyScanWithPCLReader (benchmark::State& state)
  {
    if (!haveBunny (state))
      return;
    for (auto _ : state)
    {
      pcl::PointCloud<pcl::PointXYZ> cloud;
      benchmark::DoNotOptimize (pcl::PLYReader ().read (kBunny, cloud));
    }
  }

  void
  BM_TriangulateBunny (benchmark::State& state)
  {
    if (!haveBunny (state))
      return;
    pcl::RangeScanTriangulation triangulation;
    triangulation.setViewpoint (bunny ().viewpoint);
    triangulation.setForceDelaunay (state.range (0) != 0);
    for (auto _ : state)
    {
      pcl::ScanMesh mesh;
      triangulation.triangulate (*bunny ().cloud, mesh);
      benchmark::DoNotOptimize (mesh.polygons.data ());
    }
  }

  void
  BM_ReduceBunny (benchmark::State& state)
  {
    if (!haveBunny (state))
      return;
    pcl::RangeScanTriangulation triangulation;
    pcl::ScanMesh fine;
    triangulation.triangulate (*bunny ().cloud, fine);
    pcl::QuadricMeshReduction reduction;
    reduction.setTargetFaces (static_cast<int> (state.range (0)));
    for (auto _ : state)
    {
      pcl::ScanMesh reduced;
      reduction.reduce (fine, reduced);
      benchmark::DoNotOptimize (reduced.polygons.data ());
    }
  }

  void
  BM_PrepareBunny (benchmark::State& state)
  {
    if (!haveBunny (state))
      return;
    pcl::ScanPreparationParams params;
    params.normal_method = static_cast<pcl::ScanMeshNormalEstimation::Method> (state.range (0));
    for (auto _ : state)
      benchmark::DoNotOptimize (pcl::prepareScan (*bunny ().cloud, bunny ().viewpoint, params));
  }

  void
  BM_PrepareExampleView (benchmark::State& state)
  {
    // A scan-like input that needs no third-party data: the example object's vertices seen from +z.
    const pcl::ScanMesh object = pcl::makeExampleObject ();
    pcl::PointCloud<pcl::PointXYZ> cloud;
    for (const auto& p : *object.cloud)
      if (p.normal_z > 0.2f)
        cloud.push_back (pcl::PointXYZ (p.x, p.y, p.z));
    for (auto _ : state)
      benchmark::DoNotOptimize (pcl::prepareScan (cloud, pcl::ScanViewpoint::fromPositiveZ ()));
  }
}

BENCHMARK (BM_ReadBunnyScan)->Unit (benchmark::kMillisecond);
BENCHMARK (BM_ReadBunnyScanWithPCLReader)->Unit (benchmark::kMillisecond);
BENCHMARK (BM_TriangulateBunny)->Arg (0)->Arg (1)->ArgName ("delaunay")->Unit (benchmark::kMillisecond);
BENCHMARK (BM_ReduceBunny)->Arg (400)->ArgName ("faces")->Unit (benchmark::kMillisecond);
BENCHMARK (BM_PrepareBunny)->Arg (0)->Arg (1)->ArgName ("normal_method")->Unit (benchmark::kMillisecond);
BENCHMARK (BM_PrepareExampleView)->Unit (benchmark::kMillisecond);
BENCHMARK_MAIN ();
