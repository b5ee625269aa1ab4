/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/surface/scan_volumetric_integration.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/common/time.h>
#include <pcl/surface/range_view_projection.h>

#include "tsdf_block_volume.h"
#include "../common/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <unordered_set>

namespace pcl
{
  namespace
  {
    using detail::kBlockSide;
    using detail::TsdfBlockVolume;

    /** Each view's z-buffer is capped at 16 Mpixels (64 MiB of triangle indices). */
    constexpr std::size_t kMaxZBufferPixels = std::size_t (16) << 20;

    /** Floor division of a voxel coordinate into its block coordinate. */
    int
    blockOf (int voxel)
    {
      return voxel >= 0 ? voxel / kBlockSide : -((-voxel + kBlockSide - 1) / kBlockSide);
    }

    /** The blocks within \a margin (metres) of a triangle of \a view, each once, in the order its
      * triangles first reach them: the signed distance band of a view lies within truncation of its
      * surface. Consecutive triangles of a scan mostly fall in the same blocks, so a repeated block
      * range is skipped. Stops after \a max_blocks blocks, or at the first block out of the volume's
      * range: either way registering them throws. */
    std::vector<Eigen::Vector3i>
    viewBlocks (const IntegrationView& view, double margin, double voxel_size, std::size_t max_blocks)
    {
      const double inv = 1.0 / voxel_size;
      const auto& cloud = *view.mesh->cloud;
      std::vector<Eigen::Vector3d> world (cloud.size ());
      for (std::size_t i = 0; i < cloud.size (); ++i)
        world[i] = view.pose * cloud[i].getVector3fMap ().cast<double> ();
      std::vector<Eigen::Vector3i> blocks;
      std::unordered_set<std::uint64_t> seen;
      Eigen::Vector3i last_lo (1, 1, 1), last_hi (0, 0, 0);
      for (const auto& poly : view.mesh->polygons)
      {
        Eigen::Vector3d lo = world[poly.vertices[0]], hi = lo;
        for (int k = 1; k < 3; ++k)
        {
          lo = lo.cwiseMin (world[poly.vertices[k]]);
          hi = hi.cwiseMax (world[poly.vertices[k]]);
        }
        Eigen::Vector3i blo, bhi;
        for (int k = 0; k < 3; ++k)
        {
          const double a = std::floor ((lo[k] - margin) * inv), b = std::ceil ((hi[k] + margin) * inv);
          // Out-of-range coordinates are refused by reserveBlock; clamp before converting to int.
          const double limit = 2.0 * TsdfBlockVolume::kMaxBlockCoordinate * kBlockSide;
          blo[k] = blockOf (static_cast<int> (std::max (-limit, std::min (limit, a))));
          bhi[k] = blockOf (static_cast<int> (std::max (-limit, std::min (limit, b))));
        }
        if (blo == last_lo && bhi == last_hi)
          continue;
        last_lo = blo;
        last_hi = bhi;
        for (int z = blo.z (); z <= bhi.z (); ++z)
          for (int y = blo.y (); y <= bhi.y (); ++y)
            for (int x = blo.x (); x <= bhi.x (); ++x)
            {
              const Eigen::Vector3i block (x, y, z);
              if (!TsdfBlockVolume::inRange (block))
              {
                blocks.push_back (block);  // reserveBlock () refuses it, with the message
                return blocks;
              }
              if (!seen.insert (TsdfBlockVolume::key (block)).second)
                continue;
              blocks.push_back (block);
              if (blocks.size () > max_blocks)
                return blocks;
            }
      }
      return blocks;
    }

    /** Register every block near a triangle of any view, in the order a pass over the views in turn
      * first reaches them (so the volume, and the mesh, are the same at any thread count). Each view's
      * blocks are found on its own thread. */
    void
    reserveBlocks (const std::vector<IntegrationView>& views, double margin, std::size_t max_blocks, unsigned threads,
                   TsdfBlockVolume& volume)
    {
      std::vector<std::vector<Eigen::Vector3i>> blocks (views.size ());
      pcl::detail::parallelFor (views.size (), threads, [&] (std::size_t i) {
        blocks[i] = viewBlocks (views[i], margin, volume.voxelSize (), max_blocks);
      });
      for (auto& view : blocks)
      {
        for (const auto& block : view)
          volume.reserveBlock (block);
        std::vector<Eigen::Vector3i> ().swap (view);
      }
    }

    /** Curless & Levoy's weight behind the surface: full up to half the truncation, then falling
      * linearly to 0 at the truncation, so that a thin part's far side is not pulled by the near one. */
    float
    behindTaper (float distance, float truncation)
    {
      return distance >= -0.5f * truncation ? 1.0f : std::max (0.0f, 2.0f * (1.0f + distance / truncation));
    }

    /** Add one view's truncated signed distances to the voxels near its surface, on \a threads threads,
      * each block on one. Whole blocks are skipped when the z-buffer says every voxel is more than the
      * truncation from the surface. */
    void
    integrateView (const RangeViewProjection& projection, const Eigen::Affine3d& world_to_scan, float truncation,
                   unsigned threads, TsdfBlockVolume& volume)
    {
      const Eigen::Affine3f world_to_sensor = projection.getScanToSensor () * world_to_scan.cast<float> ();
      const float s = static_cast<float> (volume.voxelSize ());
      const Eigen::Matrix3f step = world_to_sensor.linear () * s;
      pcl::detail::parallelFor (volume.blockCount (), threads, [&] (std::size_t b) {
        const Eigen::Vector3f origin = world_to_sensor * (volume.blockCoordinates (b).cast<float> () * (kBlockSide * s));
        // The block's corner voxels in the sensor frame bound all its voxels.
        Eigen::Vector3f lo = origin, hi = origin;
        for (int k = 1; k < 8; ++k)
        {
          const Eigen::Vector3f c = origin + step * (Eigen::Vector3f ((k & 1), (k >> 1) & 1, (k >> 2) & 1) * (kBlockSide - 1));
          lo = lo.cwiseMin (c);
          hi = hi.cwiseMax (c);
        }
        float min_depth, max_depth;
        if (!projection.depthRange (lo, hi, min_depth, max_depth))
          return;
        // Along a line of sight the range difference is at least the depth difference.
        if (lo.z () > max_depth + truncation || hi.z () < min_depth - truncation)
          return;
        detail::TsdfBlock& block = volume.block (b);
        RangeViewProjection::Sample sample;
        int i = 0;
        for (int z = 0; z < kBlockSide; ++z)
          for (int y = 0; y < kBlockSide; ++y)
          {
            Eigen::Vector3f p = origin + step.col (1) * static_cast<float> (y) + step.col (2) * static_cast<float> (z);
            for (int x = 0; x < kBlockSide; ++x, ++i, p += step.col (0))
            {
              if (!projection.sampleSensor (p, sample) || sample.distance > truncation || sample.distance < -truncation)
                continue;
              const float w = sample.weight * behindTaper (sample.distance, truncation);
              if (!(w > 0.0f))
                continue;
              detail::TsdfVoxel& v = block[i];
              const float total = v.weight + w;
              v.distance = (v.distance * v.weight + sample.distance * w) / total;
              v.weight = total;
            }
          }
      });
    }

    static_assert (IntegrationVolume::kBlockVoxels == detail::kBlockVoxels, "an IntegrationVolume block is a TsdfBlock");

    /** The first blocks of \a volume, reserved from \a initial in its order, take its voxels. */
    void
    restoreVoxels (const IntegrationVolume& initial, TsdfBlockVolume& volume)
    {
      for (std::size_t b = 0; b < initial.blocks.size (); ++b)
      {
        detail::TsdfBlock& block = volume.block (b);
        const std::size_t first = b * IntegrationVolume::kBlockVoxels;
        for (std::size_t v = 0; v < block.size (); ++v)
          block[v] = {initial.distance[first + v], initial.weight[first + v]};
      }
    }

    /** A copy of \a volume's voxels, to add views to later. */
    IntegrationVolume::Ptr
    keptVoxels (const TsdfBlockVolume& volume, std::size_t views, double resolution_sum)
    {
      auto kept = std::make_shared<IntegrationVolume> ();
      kept->voxel_size = volume.voxelSize ();
      kept->views = views;
      kept->resolution_sum = resolution_sum;
      kept->blocks.reserve (volume.blockCount ());
      kept->distance.reserve (volume.blockCount () * IntegrationVolume::kBlockVoxels);
      kept->weight.reserve (kept->distance.capacity ());
      for (std::size_t b = 0; b < volume.blockCount (); ++b)
      {
        kept->blocks.push_back (volume.blockCoordinates (b));
        for (const auto& v : volume.block (b))
        {
          kept->distance.push_back (v.distance);
          kept->weight.push_back (v.weight);
        }
      }
      return kept;
    }

    /** Union-find root with path halving. */
    std::uint32_t
    findRoot (std::vector<std::uint32_t>& parent, std::uint32_t v)
    {
      while (parent[v] != v)
        v = parent[v] = parent[parent[v]];
      return v;
    }

    /** Drop the connected pieces with fewer than \a min_fraction of all triangles; returns the number
      * of pieces found and records those removed. */
    std::size_t
    removeSmallComponents (std::size_t vertex_count, std::vector<Eigen::Vector3i>& triangles, double min_fraction,
                           VolumetricIntegrationReport& report)
    {
      std::vector<std::uint32_t> parent (vertex_count);
      std::iota (parent.begin (), parent.end (), 0u);
      for (const auto& t : triangles)
        for (int k = 1; k < 3; ++k)
        {
          const std::uint32_t a = findRoot (parent, t[0]), b = findRoot (parent, t[k]);
          if (a != b)
            parent[std::max (a, b)] = std::min (a, b);
        }
      std::vector<std::size_t> size (vertex_count, 0);
      for (const auto& t : triangles)
        ++size[findRoot (parent, t[0])];
      std::size_t components = 0;
      const double min_triangles = min_fraction * static_cast<double> (triangles.size ());
      for (std::size_t v = 0; v < vertex_count; ++v)
        if (size[v] > 0)
        {
          ++components;
          if (static_cast<double> (size[v]) < min_triangles)
          {
            ++report.removed_components;
            report.removed_triangles += size[v];
          }
        }
      triangles.erase (std::remove_if (triangles.begin (), triangles.end (),
                                       [&] (const Eigen::Vector3i& t) {
                                         return static_cast<double> (size[findRoot (parent, t[0])]) < min_triangles;
                                       }),
                       triangles.end ());
      return components;
    }

    /** The mesh with only the vertices that triangles use, and area-weighted vertex normals. */
    void
    buildModel (const std::vector<Eigen::Vector3f>& vertices, const std::vector<Eigen::Vector3i>& triangles, ScanMesh& model)
    {
      std::vector<std::int64_t> remap (vertices.size (), -1);
      model.cloud.reset (new pcl::PointCloud<pcl::PointNormal>);
      model.polygons.clear ();
      model.polygons.reserve (triangles.size ());
      std::vector<Eigen::Vector3f> normals;
      for (const auto& t : triangles)
      {
        pcl::Vertices poly;
        poly.vertices.resize (3);
        for (int k = 0; k < 3; ++k)
        {
          if (remap[t[k]] < 0)
          {
            remap[t[k]] = static_cast<std::int64_t> (model.cloud->size ());
            pcl::PointNormal p;
            p.getVector3fMap () = vertices[t[k]];
            p.curvature = 0.0f;
            model.cloud->push_back (p);
            normals.emplace_back (Eigen::Vector3f::Zero ());
          }
          poly.vertices[k] = static_cast<pcl::index_t> (remap[t[k]]);
        }
        const Eigen::Vector3f n = (vertices[t[1]] - vertices[t[0]]).cross (vertices[t[2]] - vertices[t[0]]);
        for (int k = 0; k < 3; ++k)
          normals[poly.vertices[k]] += n;
        model.polygons.push_back (std::move (poly));
      }
      for (std::size_t i = 0; i < normals.size (); ++i)
        (*model.cloud)[i].getNormalVector3fMap () = normals[i].normalized ();
    }
  }

  void
  ScanVolumetricIntegration::setParams (const VolumetricIntegrationParams& params)
  {
    if (!(params.voxel_size >= 0.0) || !(params.voxel_size_resolutions > 0.0) || !(params.truncation_voxels > 0.0)
        || !(params.border_ramp_edges > 0.0) || !(params.pixels_per_resolution > 0.0)
        || !(params.min_component_fraction >= 0.0 && params.min_component_fraction < 1.0))
      PCL_TENSOR_THROW (pcl::BadArgumentException,
                        "volumetric integration: voxel size must be >= 0, the relative voxel size, truncation, border "
                        "ramp and pixel density > 0, the component fraction in [0, 1)");
    params_ = params;
  }

  void
  ScanVolumetricIntegration::setVoxelSize (double size)
  {
    VolumetricIntegrationParams p = params_;
    p.voxel_size = size;
    setParams (p);
  }

  void
  ScanVolumetricIntegration::setMaxMemoryBytes (std::size_t bytes)
  {
    params_.max_memory_bytes = bytes;
  }

  void
  ScanVolumetricIntegration::checkInput () const
  {
    if (views_.empty () && !initial_)
      PCL_TENSOR_THROW (InvalidScanException, "volumetric integration: no views");
    for (std::size_t i = 0; i < views_.size (); ++i)
      if (!views_[i].mesh || views_[i].mesh->polygons.empty ())
        PCL_TENSOR_THROW (InvalidScanException, "volumetric integration: view " << i << " has no triangle");
    if (initial_ && !initial_->isConsistent ())
      PCL_TENSOR_THROW (InvalidScanException, "volumetric integration: the initial volume's sizes do not agree");
  }

  void
  ScanVolumetricIntegration::reconstruct (ScanMesh& model)
  {
    report_ = VolumetricIntegrationReport ();
    volume_.reset ();
    checkInput ();
    std::vector<double> resolutions (views_.size ());
    pcl::detail::parallelFor (views_.size (), threads_, [&] (std::size_t i) { resolutions[i] = meshResolution (*views_[i].mesh); });
    // An initial volume keeps its voxel size; its views count in the mean d_res.
    report_.initial_views = initial_ ? initial_->views : 0;
    report_.views = views_.size () + report_.initial_views;
    const double resolution_sum = std::accumulate (resolutions.begin (), resolutions.end (), initial_ ? initial_->resolution_sum : 0.0);
    report_.resolution = report_.views > 0 ? resolution_sum / static_cast<double> (report_.views) : 0.0;
    report_.voxel_size = initial_ ? initial_->voxel_size : params_.voxel_size > 0.0 ? params_.voxel_size :
                         params_.voxel_size_resolutions * report_.resolution;
    const float truncation = static_cast<float> (params_.truncation_voxels * report_.voxel_size);

    pcl::StopWatch watch;
    const std::size_t max_blocks = params_.max_memory_bytes / TsdfBlockVolume::bytesPerBlock ();
    TsdfBlockVolume volume (report_.voxel_size, max_blocks);
    if (initial_)
      for (const auto& block : initial_->blocks)
        volume.reserveBlock (block);
    reserveBlocks (views_, truncation + report_.voxel_size, max_blocks, threads_, volume);
    volume.allocate ();
    if (initial_)
      restoreVoxels (*initial_, volume);
    report_.blocks = volume.blockCount ();
    report_.voxels = report_.blocks * detail::kBlockVoxels;
    report_.volume_bytes = volume.memoryBytes ();
    report_.allocate_ms = watch.getTime ();

    watch.reset ();
    // A view's z-buffer is drawn on one thread: as many as there are threads are drawn at once, then
    // integrated in order, so that memory holds that many z-buffers at most.
    const std::size_t chunk = pcl::detail::threadCount (threads_);
    for (std::size_t first = 0; first < views_.size (); first += chunk)
    {
      std::vector<std::unique_ptr<RangeViewProjection>> projections (std::min (chunk, views_.size () - first));
      pcl::detail::parallelFor (projections.size (), threads_, [&] (std::size_t k) {
        projections[k] = std::make_unique<RangeViewProjection> (*views_[first + k].mesh, params_.border_ramp_edges,
                                                                params_.pixels_per_resolution, kMaxZBufferPixels,
                                                                resolutions[first + k]);
      });
      for (std::size_t k = 0; k < projections.size (); ++k)
      {
        report_.peak_zbuffer_bytes = std::max (report_.peak_zbuffer_bytes, projections[k]->memoryBytes ());
        integrateView (*projections[k], views_[first + k].pose.inverse (), truncation, threads_, volume);
      }
    }
    for (std::size_t b = 0; b < volume.blockCount (); ++b)
      for (const auto& v : volume.block (b))
        report_.observed_voxels += v.weight > 0.0f ? 1 : 0;
    if (keep_volume_)
      volume_ = keptVoxels (volume, report_.views, resolution_sum);
    report_.integrate_ms = watch.getTime ();

    watch.reset ();
    std::vector<Eigen::Vector3f> vertices;
    std::vector<Eigen::Vector3i> triangles;
    detail::extractZeroSet (volume, vertices, triangles, threads_);
    report_.extract_ms = watch.getTime ();

    watch.reset ();
    report_.components = removeSmallComponents (vertices.size (), triangles, params_.min_component_fraction, report_);
    buildModel (vertices, triangles, model);
    model.viewpoint = ScanViewpoint ();
    report_.cleanup_ms = watch.getTime ();
  }

  void
  ScanVolumetricIntegration::reconstruct (pcl::PolygonMesh& model)
  {
    ScanMesh mesh;
    reconstruct (mesh);
    toPolygonMesh (mesh, model);
  }
}
