/*
 * eval_integration: volumetric integration (Curless & Levoy 1996) of the Stanford dragon_stand scans at
 * their ground-truth poses, timed by stage and compared with VripPack's own model (issue 6).
 *
 *   eval_integration [--conf FILE] [--reference PLY] [--voxel-res R[,R...]] [--out PLY]   (see --help)
 *
 * Third-party data is read from ../shared/data (PCL_TENSOR_SHARED_DATA) or --data DIR.
 */
#include "eval/eval_views.h"

#include <pcl/common/point_mesh_distance.h>
#include <pcl/common/time.h>
#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/io/ply_io.h>
#include <pcl/io/stanford_conf.h>
#include <pcl/registration/multiview_point_to_plane_icp.h>
#include <pcl/registration/registration_error.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/simulation/example_object.h>
#include <pcl/io/scan_mesh_io.h>
#include <pcl/surface/range_scan_triangulation.h>
#include <pcl/surface/scan_volumetric_integration.h>

#include <algorithm>
#include <ctime>
#include <cstdio>
#include <filesystem>
#include <sstream>

using namespace pcl_tensor_eval;

namespace
{
  struct Options
  {
    std::string data = PCL_TENSOR_SHARED_DATA;
    std::string conf;       ///< default: <data>/stanford/dragon_stand/dragonStandRight.conf
    std::string reference;  ///< default: <data>/stanford/dragon_recon/dragon_vrip_res3.ply
    std::vector<double> voxel_res{1.0};
    std::string out = "/tmp/eval_integration_model.ply";
    bool synthetic = false;  ///< the 26 synthetic views of the built-in object instead of the scans
    std::string model;       ///< a model already made (pcl_tensor_model -o), scored instead of integrating
    std::string poses;       ///< the estimated poses it was made with (pcl_tensor_model's .conf)
    pcl::VolumetricIntegrationParams params;
  };

  void
  printHelp (const char* name)
  {
    const Options d;
    std::printf ("Volumetric integration of registered scans at their .conf poses, compared with a reference model.\n\n"
                 "Usage: %s [options]\n\n"
                 "  --synthetic         the 26 synthetic views of the built-in example object at their exact poses,\n"
                 "                      compared with the object itself (issue 6's Fig. 12 criterion)\n"
                 "  --data DIR          third-party data (default %s)\n"
                 "  --conf FILE         scans and poses (default DATA/stanford/dragon_stand/dragonStandRight.conf)\n"
                 "  --reference PLY     model to compare with (default DATA/stanford/dragon_recon/dragon_vrip_res3.ply)\n"
                 "  --voxel-res R,...   voxel sizes in d_res, one run each (default 1)\n"
                 "  --trunc T           truncation in voxels (default %g)\n"
                 "  --ramp E            border weight ramp in edges (default %g)\n"
                 "  --min-piece F       drop surface pieces under this fraction of the triangles (default %g)\n"
                 "  --out PLY           model of the last run (default %s)\n"
                 "  --model PLY         score this model (e.g. pcl_tensor_model's) instead of integrating: it is moved\n"
                 "                      into the reference's frame by the frame that fits its poses best to --conf\n"
                 "                      (pcl::bestFitCommonFrame), and by view 0's true pose, and scored both ways\n"
                 "  --poses CONF        the estimated poses the model was made with (default: the model's name with .conf)\n"
                 "                      (with --synthetic: --conf is pcl_tensor_views' views.conf, the reference the built-in object)\n",
                 name, d.data.c_str (), d.params.truncation_voxels, d.params.border_ramp_edges,
                 d.params.min_component_fraction, d.out.c_str ());
  }

  double
  percentile (std::vector<double> values, double q)
  {
    const std::size_t k = std::min (values.size () - 1, static_cast<std::size_t> (q * values.size ()));
    std::nth_element (values.begin (), values.begin () + k, values.end ());
    return values[k];
  }

  /** Distances from every vertex of \a from to the surface of \a to, in units of \a unit. */
  std::vector<double>
  distances (const pcl::ScanMesh& from, const pcl::ScanMesh& to, double unit)
  {
    pcl::PointMeshDistance index;
    index.setMesh (to);
    std::vector<double> d;
    d.reserve (from.cloud->size ());
    for (const auto& p : *from.cloud)
      d.push_back (index.distance (p.getVector3fMap ().cast<double> ()) / unit);
    return d;
  }

  /** The fraction of the reference's vertices with no scan point (at its pose) within \a radius_res d_res. */
  double
  unseenFraction (const std::vector<pcl::IntegrationView>& views, const pcl::ScanMesh& reference, double radius_res)
  {
    pcl::PointCloud<pcl::PointXYZ>::Ptr all (new pcl::PointCloud<pcl::PointXYZ>);
    double resolution = 0.0;
    for (const auto& v : views)
    {
      resolution += pcl::meshResolution (*v.mesh) / views.size ();
      for (const auto& p : *v.mesh->cloud)
      {
        pcl::PointXYZ q;
        q.getVector3fMap () = (v.pose * p.getVector3fMap ().cast<double> ()).cast<float> ();
        all->push_back (q);
      }
    }
    pcl::KdTreeFLANN<pcl::PointXYZ> tree;
    tree.setInputCloud (all);
    std::size_t unseen = 0;
    std::vector<int> index (1);
    std::vector<float> sqr (1);
    for (const auto& p : *reference.cloud)
    {
      pcl::PointXYZ q (p.x, p.y, p.z);
      tree.nearestKSearch (q, 1, index, sqr);
      unseen += std::sqrt (sqr[0]) > radius_res * resolution ? 1 : 0;
    }
    return static_cast<double> (unseen) / reference.cloud->size ();
  }

  /** The estimated poses of \a scans, read from \a path and matched to the scans by file name. */
  pcl::registration::ViewPoses
  estimatedPoses (const EvalViews& scans, const std::string& path)
  {
    const auto entries = pcl::io::loadStanfordConf (path);
    pcl::registration::ViewPoses poses;
    for (const auto& s : scans)
    {
      const auto it = std::find_if (entries.begin (), entries.end (), [&] (const pcl::io::StanfordConfEntry& e)
                                    { return std::filesystem::path (e.file).stem ().string () == s.name; });
      if (it == entries.end ())
        throw std::runtime_error ("no pose for scan '" + s.name + "' in " + path);
      poses.push_back (it->pose ());
    }
    return poses;
  }

  void
  printDistances (const char* label, const pcl::ScanMesh& model, const Eigen::Affine3d& frame, const pcl::ScanMesh& reference,
                  double resolution)
  {
    pcl::ScanMesh moved = model;
    moved.cloud.reset (new pcl::PointCloud<pcl::PointNormal> (*model.cloud));
    for (auto& p : *moved.cloud)
      p.getVector3fMap () = (frame * p.getVector3fMap ().cast<double> ()).cast<float> ();
    const auto accuracy = distances (moved, reference, resolution);
    const auto coverage = distances (reference, moved, resolution);
    std::printf ("  %-28s model -> reference median %.3f p95 %.3f d_res; reference -> model median %.3f p95 %.3f d_res\n", label,
                 percentile (accuracy, 0.5), percentile (accuracy, 0.95), percentile (coverage, 0.5), percentile (coverage, 0.95));
  }

  /** Scores a model made from \a scans at estimated poses against \a reference, in two common frames. */
  void
  scoreModel (const Options& o, const EvalViews& scans, const pcl::ScanMesh& reference)
  {
    const std::string poses_path = o.poses.empty () ? std::filesystem::path (o.model).replace_extension (".conf").string () : o.poses;
    const auto estimates = estimatedPoses (scans, poses_path);
    std::vector<const pcl::PointCloud<pcl::PointXYZ>*> clouds;
    pcl::registration::ViewPoses truth;
    double resolution = 0.0;
    for (const auto& s : scans)
    {
      clouds.push_back (s.cloud.get ());
      truth.push_back (s.pose);
      pcl::RangeScanTriangulation triangulation;
      triangulation.setViewpoint (s.viewpoint);
      pcl::ScanMesh mesh;
      triangulation.triangulate (*s.cloud, mesh);
      resolution += pcl::meshResolution (mesh) / scans.size ();
    }
    const pcl::ScanMesh model = pcl::io::loadScanMesh (o.model);
    std::printf ("%s (%zu vertices, %zu triangles), poses %s, d_res %.4f mm\n", o.model.c_str (), model.cloud->size (),
                 model.polygons.size (), poses_path.c_str (), resolution * 1e3);
    const Eigen::Affine3d best = pcl::bestFitCommonFrame (clouds, estimates, truth);
    printDistances ("best-fit common frame:", model, best, reference, resolution);
    printDistances ("view 0 at its true pose:", model, scans.front ().pose * estimates.front ().inverse (), reference, resolution);
  }

  Eigen::Vector3f
  extent (const pcl::ScanMesh& mesh)
  {
    Eigen::Vector3f lo = Eigen::Vector3f::Constant (1e30f), hi = -lo;
    for (const auto& p : *mesh.cloud)
    {
      lo = lo.cwiseMin (p.getVector3fMap ());
      hi = hi.cwiseMax (p.getVector3fMap ());
    }
    return hi - lo;
  }
}

int
main (int argc, char** argv)
{
  if (pcl::console::find_switch (argc, argv, "--help") || pcl::console::find_switch (argc, argv, "-h"))
  {
    printHelp (argv[0]);
    return 0;
  }
  Options o;
  pcl::console::parse_argument (argc, argv, "--data", o.data);
  o.conf = o.data + "/stanford/dragon_stand/dragonStandRight.conf";
  o.reference = o.data + "/stanford/dragon_recon/dragon_vrip_res3.ply";
  pcl::console::parse_argument (argc, argv, "--conf", o.conf);
  pcl::console::parse_argument (argc, argv, "--reference", o.reference);
  pcl::console::parse_argument (argc, argv, "--out", o.out);
  pcl::console::parse_argument (argc, argv, "--trunc", o.params.truncation_voxels);
  pcl::console::parse_argument (argc, argv, "--ramp", o.params.border_ramp_edges);
  pcl::console::parse_argument (argc, argv, "--min-piece", o.params.min_component_fraction);
  pcl::console::parse_x_arguments (argc, argv, "--voxel-res", o.voxel_res);
  o.synthetic = pcl::console::find_switch (argc, argv, "--synthetic");
  pcl::console::parse_argument (argc, argv, "--model", o.model);
  pcl::console::parse_argument (argc, argv, "--poses", o.poses);
  pcl::console::setVerbosityLevel (pcl::console::L_ERROR);

  try
  {
    pcl::StopWatch watch;
    const pcl::ScanMesh object = o.synthetic ? pcl::makeExampleObject () : pcl::ScanMesh ();
    if (!o.model.empty ())
    {
      // The views the model was made from, with their true poses (--conf: pcl_tensor_views' views.conf
      // for synthetic views of the built-in object).
      scoreModel (o, loadStanfordViews (o.conf), o.synthetic ? object : pcl::io::loadScanMesh (o.reference));
      return 0;
    }
    EvalViews scans = o.synthetic ? makeSyntheticViews (object, pcl::SyntheticViewParams ()) : loadStanfordViews (o.conf);
    const double load_ms = watch.getTime ();

    watch.reset ();
    std::vector<pcl::IntegrationView> views;
    std::size_t points = 0;
    for (const auto& s : scans)
    {
      pcl::RangeScanTriangulation triangulation;
      triangulation.setViewpoint (s.viewpoint);
      auto mesh = std::make_shared<pcl::ScanMesh> ();
      triangulation.triangulate (*s.cloud, *mesh);
      points += mesh->cloud->size ();
      views.push_back ({mesh, s.pose});
    }
    const double mesh_ms = watch.getTime ();
    const pcl::ScanMesh reference = o.synthetic ? object : pcl::io::loadScanMesh (o.reference);
    std::printf ("%zu %s, %zu points: %s %.0f ms, meshing M_i %.0f ms; reference %zu vertices\n", views.size (),
                 o.synthetic ? "synthetic views" : "scans", points, o.synthetic ? "rendering" : "loading", load_ms,
                 mesh_ms, reference.cloud->size ());
    std::printf ("%.1f%% of the reference is farther than 2 d_res from every scan point (seen by no scan)\n",
                 100.0 * unseenFraction (views, reference, 2.0));

    std::printf ("%6s %9s %8s %9s %7s %7s %7s %7s %7s %8s %7s %8s %7s %8s %8s %8s %8s\n", "voxel", "voxel_mm", "blocks",
                 "voxels", "MiB", "alloc", "integr", "mc", "clean", "total_ms", "cpu_ms", "tris", "pieces", "med_res",
                 "p95_res", "cov_med", "cov_p95");
    for (const double res : o.voxel_res)
    {
      pcl::VolumetricIntegrationParams params = o.params;
      params.voxel_size_resolutions = res;
      pcl::ScanVolumetricIntegration integration;
      integration.setParams (params);
      integration.setInputViews (views);
      pcl::ScanMesh model;
      const std::clock_t cpu = std::clock ();
      integration.reconstruct (model);
      const double cpu_ms = 1e3 * static_cast<double> (std::clock () - cpu) / CLOCKS_PER_SEC;
      const auto& r = integration.getReport ();
      // Model -> reference: accuracy; reference -> model: coverage (holes show up there).
      const auto accuracy = distances (model, reference, r.resolution);
      const auto coverage = distances (reference, model, r.resolution);
      std::printf ("%6.2f %9.4f %8zu %9zu %7.1f %7.0f %7.0f %7.0f %7.0f %8.0f %7.0f %8zu %7zu %8.3f %8.3f %8.3f %8.3f\n", res,
                   r.voxel_size * 1e3, r.blocks, r.voxels, (r.volume_bytes + r.peak_zbuffer_bytes) / 1048576.0,
                   r.allocate_ms, r.integrate_ms, r.extract_ms, r.cleanup_ms,
                   r.allocate_ms + r.integrate_ms + r.extract_ms + r.cleanup_ms, cpu_ms, model.polygons.size (),
                   r.components - r.removed_components, percentile (accuracy, 0.5), percentile (accuracy, 0.95),
                   percentile (coverage, 0.5), percentile (coverage, 0.95));
      const Eigen::Vector3f e = extent (model), er = extent (reference);
      std::printf ("       d_res %.4f mm; observed voxels %zu; removed %zu pieces (%zu triangles); extent %.1f x %.1f x %.1f mm"
                   " (reference %.1f x %.1f x %.1f)\n",
                   r.resolution * 1e3, r.observed_voxels, r.removed_components, r.removed_triangles, e.x () * 1e3,
                   e.y () * 1e3, e.z () * 1e3, er.x () * 1e3, er.y () * 1e3, er.z () * 1e3);
      // Where the reference has surface the model lacks (VripPack fills unseen holes, e.g. under the base).
      Eigen::Vector3f miss_lo = Eigen::Vector3f::Constant (1e30f), miss_hi = -miss_lo;
      std::size_t missed = 0;
      for (std::size_t i = 0; i < coverage.size (); ++i)
        if (coverage[i] > 2.0)
        {
          ++missed;
          miss_lo = miss_lo.cwiseMin ((*reference.cloud)[i].getVector3fMap ());
          miss_hi = miss_hi.cwiseMax ((*reference.cloud)[i].getVector3fMap ());
        }
      if (missed > 0)
        std::printf ("       %.1f%% of the reference farther than 2 d_res from the model, within y %.1f..%.1f mm\n",
                     100.0 * missed / coverage.size (), miss_lo.y () * 1e3, miss_hi.y () * 1e3);
      if (res == o.voxel_res.back ())
      {
        pcl::PolygonMesh out;
        pcl::toPolygonMesh (model, out);
        pcl::io::savePLYFileBinary (o.out, out);
        std::printf ("model written to %s\n", o.out.c_str ());
      }
    }
  }
  catch (const std::exception& e)
  {
    std::fprintf (stderr, "eval_integration: %s\n", e.what ());
    return 1;
  }
  return 0;
}
