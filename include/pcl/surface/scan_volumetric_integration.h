/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_mesh.h>
#include <pcl/surface/integration_volume.h>
#include <pcl/PolygonMesh.h>
#include <Eigen/Geometry>

#include <cstddef>
#include <vector>

namespace pcl
{
  /** \brief One registered range view: its fine mesh M_i in its own scan frame (with the viewpoint
    * that saw it) and its pose into the world frame.
    *
    * The mesh is shared, not copied; a view held inside a larger object can be passed with shared_ptr's
    * aliasing constructor, e.g. ScanMesh::ConstPtr (prepared, &prepared->fine).
    * \ingroup surface
    */
  struct IntegrationView
  {
    /** The view's triangle mesh in its scan frame; never null when integrated. */
    ScanMesh::ConstPtr mesh;
    /** Maps scan-frame points into the world frame (p_world = pose * p), e.g. StanfordConfEntry::pose(). */
    Eigen::Affine3d pose = Eigen::Affine3d::Identity ();
  };

  /** \brief Parameters of the volumetric integration (Section 5's modelling step; Curless & Levoy 1996).
    * \note The paper runs VripPack; these defaults are ours (doc/design.md#volumetric-integration).
    * \ingroup surface
    */
  struct VolumetricIntegrationParams
  {
    /** Voxel edge in metres; 0 means voxel_size_resolutions times the mean d_res of the views. */
    double voxel_size = 0.0;
    /** Voxel edge in units of the views' mean d_res, used when voxel_size is 0. */
    double voxel_size_resolutions = 1.0;
    /** Signed distances are kept within +-truncation_voxels voxels of each view's surface along its
      * lines of sight; farther voxels are not updated (Curless & Levoy's ramp). */
    double truncation_voxels = 3.0;
    /** Weights rise from 0 on each view's mesh border to full weight this many edges inside. */
    double border_ramp_edges = 3.0;
    /** Z-buffer pixels per d_res of each view, on its retinal plane. */
    double pixels_per_resolution = 2.0;
    /** Refuse (MemoryLimitException) a voxel volume that would need more bytes than this. */
    std::size_t max_memory_bytes = std::size_t (2) << 30;
    /** Drop connected pieces of the surface with fewer than this fraction of its triangles (0 keeps all). */
    double min_component_fraction = 0.001;
  };

  /** \brief What one integration did: sizes, memory and the time of each stage.
    * \ingroup surface
    */
  struct VolumetricIntegrationReport
  {
    double voxel_size = 0.0;           ///< the voxel edge used, in metres
    double resolution = 0.0;           ///< mean d_res of the views, in metres
    std::size_t views = 0;             ///< views integrated (with those of the initial volume)
    std::size_t initial_views = 0;     ///< of them, those integrated before (setInitialVolume())
    std::size_t blocks = 0;            ///< allocated 8^3 voxel blocks
    std::size_t voxels = 0;            ///< allocated voxels (blocks * 512)
    std::size_t observed_voxels = 0;   ///< voxels with weight > 0
    std::size_t volume_bytes = 0;      ///< memory of the voxel blocks and their index
    std::size_t peak_zbuffer_bytes = 0;  ///< largest single view's z-buffer
    std::size_t components = 0;        ///< connected pieces of the extracted surface
    std::size_t removed_components = 0;  ///< pieces dropped by min_component_fraction
    std::size_t removed_triangles = 0;   ///< their triangles
    double allocate_ms = 0.0;          ///< finding the blocks near the views' surfaces
    double integrate_ms = 0.0;         ///< z-buffers and signed distance updates of all views
    double extract_ms = 0.0;           ///< marching cubes and vertex welding
    double cleanup_ms = 0.0;           ///< component removal and normals
  };

  /** \brief Volumetric integration of registered range views into one surface, after VripPack
    * (Curless & Levoy, "A volumetric method for building complex models from range images",
    * SIGGRAPH 1996): the modelling step that follows registration in Section 5 (Figs. 1 and 9).
    *
    * Each view adds, to every voxel near its surface, the signed distance along the sensor's line of
    * sight from the voxel to the view's triangle mesh (positive on the sensor's side), truncated to
    * +-truncation_voxels, with Curless & Levoy's weights (RangeViewProjection: lower at grazing angles
    * and near mesh borders, tapering behind the surface). Voxels live in sparse 8^3 blocks hashed by
    * position, allocated only near the views' surfaces, so memory grows with the surface area, not
    * the bounding volume. Marching cubes then extracts the zero set, only in cubes whose eight corners
    * were all seen (weight > 0), so unseen space makes no surface; vertices are shared between
    * adjacent cubes, giving an indexed mesh whose normals point out of the object.
    * \ingroup surface
    */
  class ScanVolumetricIntegration
  {
    public:
      using Ptr = shared_ptr<ScanVolumetricIntegration>;
      using ConstPtr = shared_ptr<const ScanVolumetricIntegration>;

      /** \brief Set all parameters.
        * \throw pcl::BadArgumentException on a negative voxel size, a non-positive relative voxel size,
        * truncation, border ramp or pixel density, or a component fraction outside [0, 1)
        */
      void setParams (const VolumetricIntegrationParams& params);
      const VolumetricIntegrationParams& getParams () const { return params_; }

      /** \brief Set the voxel edge in metres (0: from the views' resolution). */
      void setVoxelSize (double size);
      double getVoxelSize () const { return params_.voxel_size; }

      /** \brief Set the memory limit of the voxel volume in bytes. */
      void setMaxMemoryBytes (std::size_t bytes);
      std::size_t getMaxMemoryBytes () const { return params_.max_memory_bytes; }

      /** \brief Set the threads that add a view's distances, a share of the voxel blocks each (0, the
        * default: every core). The model is the same for any number: views are added in order. */
      void setNumberOfThreads (unsigned threads) { threads_ = threads; }
      unsigned getNumberOfThreads () const { return threads_; }

      /** \brief Set the views to integrate. */
      void setInputViews (const std::vector<IntegrationView>& views) { views_ = views; }
      const std::vector<IntegrationView>& getInputViews () const { return views_; }

      /** \brief Voxels of views integrated before (getVolume() of an earlier reconstruct() with the same
        * parameters), or null (default): the input views are added to them, at their voxel size, and the
        * surface is extracted from all. A view's distances reach only blocks near its own surface, so
        * the voxels are those of integrating every view at once, up to the rounding of the order. */
      void setInitialVolume (const IntegrationVolume::ConstPtr& volume) { initial_ = volume; }
      const IntegrationVolume::ConstPtr& getInitialVolume () const { return initial_; }

      /** \brief Keep the voxels after reconstruct(), for getVolume() (default: false; they are freed). */
      void setKeepVolume (bool keep) { keep_volume_ = keep; }
      bool getKeepVolume () const { return keep_volume_; }

      /** \brief The voxels of the last reconstruct() when setKeepVolume(true), else null. */
      const IntegrationVolume::ConstPtr& getVolume () const { return volume_; }

      /** \brief Integrate the views and extract the surface in the world frame.
        * \param[out] model vertices with outward normals, and triangles; viewpoint left at its default
        * \throw InvalidScanException when there is no view and no initial volume, a mesh is null or has
        * no triangle, or the initial volume's sizes do not agree
        * \throw MemoryLimitException when the volume would exceed getMaxMemoryBytes(), before allocating it
        */
      void reconstruct (ScanMesh& model);

      /** \brief The same, as a pcl::PolygonMesh (fields x, y, z, normal_x, normal_y, normal_z, curvature). */
      void reconstruct (pcl::PolygonMesh& model);

      /** \brief What the last reconstruct() did. */
      const VolumetricIntegrationReport& getReport () const { return report_; }

    private:
      /** \throw InvalidScanException as reconstruct() */
      void checkInput () const;

      VolumetricIntegrationParams params_;
      std::vector<IntegrationView> views_;
      VolumetricIntegrationReport report_;
      unsigned threads_ = 0;
      IntegrationVolume::ConstPtr initial_;
      bool keep_volume_ = false;
      IntegrationVolume::ConstPtr volume_;
  };
}
