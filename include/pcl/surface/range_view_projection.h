/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_mesh.h>
#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace pcl
{
  /** \brief One range view seen along its sensor's lines of sight: a z-buffer of the view's triangle
    * mesh M_i in the sensor frame, answering "where along this line of sight is the surface, and how
    * much is it trusted" for any point in space. It is the per-view half of Curless & Levoy's
    * volumetric integration (SIGGRAPH 1996), used by ScanVolumetricIntegration.
    *
    * Every pixel keeps the nearest triangle whose projection covers its centre. A query point is
    * projected to its pixel and the line of sight through the point itself (not the pixel centre) is
    * intersected with that triangle's plane, so the answer is exact on the triangle and does not
    * depend on the pixel size, which only decides which triangle answers. Perspective, orthographic and
    * pushbroom sensors (ScanViewpoint::Model) are all answered this way; a pushbroom's retinal image
    * bends straight edges slightly, which again only moves which triangle answers near an edge.
    *
    * Weights follow Curless & Levoy: each vertex is weighted by the cosine between its normal
    * (area-weighted face normals, computed from the geometry) and its line of sight, times a ramp
    * that rises from 0 on the mesh's border to 1 at \a border_ramp_edges edges inside it, and the
    * weight is interpolated linearly across each triangle.
    * \ingroup surface
    */
  class RangeViewProjection
  {
    public:
      /** \brief Where a query point lies relative to the view's surface. */
      struct Sample
      {
        /** Range of the surface along the point's line of sight minus the point's range: > 0 in
          * front of the surface (the sensor's side), < 0 behind it. */
        float distance = 0.0f;
        /** The surface's weight at the hit (0..1). */
        float weight = 0.0f;
      };

      /** \brief Build the z-buffer of \a mesh, seen by its own viewpoint.
        * \param[in] mesh the view's fine mesh M_i in its scan frame, with its viewpoint
        * \param[in] border_ramp_edges weights rise from 0 on the border to 1 this many edges inside (> 0)
        * \param[in] pixels_per_resolution pixels per d_res of the mesh, on the retinal plane (> 0)
        * \param[in] max_pixels the z-buffer never exceeds this many pixels (coarser pixels instead)
        * \param[in] resolution d_res of the mesh if already known (meshResolution()); 0 computes it
        * \throw InvalidScanException when the mesh has no triangle with a finite projection
        * \throw pcl::BadArgumentException on a non-positive ramp or pixel density
        */
      RangeViewProjection (const ScanMesh& mesh, double border_ramp_edges = 3.0,
                           double pixels_per_resolution = 2.0, std::size_t max_pixels = 16u << 20,
                           double resolution = 0.0);

      /** \brief The surface along the line of sight through \a p (scan frame).
        * \param[in] p a point in the mesh's scan frame
        * \param[out] sample signed range difference and weight
        * \return false when the line of sight through \a p meets no triangle (unseen)
        */
      bool sample (const Eigen::Vector3f& p, Sample& sample) const;

      /** \brief The same for a point already in the sensor frame (see getScanToSensor()). */
      bool sampleSensor (const Eigen::Vector3f& s, Sample& sample) const;

      /** \brief Smallest and largest sensor-frame depth of the surface over the pixels a sensor-frame
        * box projects to, bounded from the z-buffer's tiles of 8 x 8 pixels that hold them (the range
        * may be wider than the box's own); false when no covered pixel is there. Lets a caller skip
        * whole regions.
        * \param[in] lo, hi opposite corners of an axis-aligned box in the sensor frame
        * \param[out] min_depth, max_depth the depth range (sensor z) of the surface seen there
        */
      bool depthRange (const Eigen::Vector3f& lo, const Eigen::Vector3f& hi, float& min_depth, float& max_depth) const;

      /** \brief Mark the lines of sight the sensor saw through: the z-buffer's pixels farther than
        * \a margin_pixels (in rows and columns) from every pixel the surface covers, and connected to
        * the z-buffer's border through such pixels (the background around the view, not a hole the
        * surface encloses, which may be a dropout). The margin keeps silhouettes, pruned depth
        * discontinuities and small dropouts from being taken for empty space.
        * seenEmpty() answers from this mask; each call replaces it.
        * \throw pcl::BadArgumentException on a negative margin
        */
      void markEmptySpace (int margin_pixels);
      /** \brief Whether the line of sight through \a p (scan frame) is one markEmptySpace() marked:
        * the sensor saw nothing anywhere along it. False outside the z-buffer (the view's own extent on
        * the retinal plane), behind the sensor, or before markEmptySpace(). */
      bool seenEmpty (const Eigen::Vector3f& p) const;
      /** \brief The transform from the scan frame into the sensor frame (inverse of the viewpoint's pose). */
      const Eigen::Affine3f& getScanToSensor () const { return scan_to_sensor_; }

      /** \brief Width and height of the z-buffer in pixels. */
      int getWidth () const { return width_; }
      int getHeight () const { return height_; }

      /** \brief Bytes held by the z-buffer and the triangle table. */
      std::size_t memoryBytes () const;

    private:
      /** A triangle: the depth at which each line of sight meets its plane, exactly, from terms affine
        * in the retinal offsets (du, dv) from the first corner (setDepthTerms, depthAs), and its weight
        * as an affine function of them. */
      struct Plane
      {
        float u, v;            ///< retinal coordinates of the triangle's first corner
        float d0, du, dv, e0;  ///< depth terms (e0: a pushbroom's denominator there)
        float w0, wu, wv;      ///< weight there, and its slopes
      };

      /** A vertex's retinal coordinates, and whether it is in front of the sensor (retinal()). */
      struct Retinal
      {
        float u = 0.0f, v = 0.0f;
        bool in_front = false;
      };

      /** Each pixel keeps the nearest triangle whose projection covers its centre. */
      template <ScanViewpoint::Model M>
      void rasterizeAs (const std::vector<Eigen::Vector3f>& sensor_points, const std::vector<Retinal>& uv,
                        const std::vector<float>& weights, const std::vector<pcl::Vertices>& polygons);
      void buildTiles ();
      bool pixelOf (float u, float v, int& col, int& row) const;
      /** Retinal coordinates of a sensor-frame point; false behind a perspective or pushbroom sensor. */
      bool retinal (const Eigen::Vector3f& s, float& u, float& v) const;
      /** The line of sight through (u, v) is o + t r with o = origin (1, u, v)^T and r = direction (1, u, v)^T,
        * o.z = 0 and r.z = 1, so that t is the depth (sensor z) of the point it reaches. */
      void rayCoefficients (Eigen::Matrix3d& origin, Eigen::Matrix3d& direction) const;
      /** The depth terms of the triangle (a, b, c) (sensor frame) about plane.u, plane.v (needs
        * ray_origin_ and ray_direction_). */
      void setDepthTerms (const Eigen::Vector3f& a, const Eigen::Vector3f& b, const Eigen::Vector3f& c, Plane& plane) const;
      /** The depth of \a plane at retinal offsets (du, dv) from its first corner, for one sensor model. */
      template <ScanViewpoint::Model M> static float depthAs (const Plane& plane, float du, float dv);
      /** sampleSensor() for one sensor model. */
      template <ScanViewpoint::Model M> bool sampleAs (const Eigen::Vector3f& s, Sample& sample) const;
      /** Depth (sensor z) at which the line of sight through (u, v) meets the triangle's plane. */
      float surfaceDepth (const Plane& plane, float u, float v) const;

      Eigen::Affine3f scan_to_sensor_ = Eigen::Affine3f::Identity ();
      Eigen::Matrix3d ray_origin_, ray_direction_;  ///< rayCoefficients(), for setDepthTerms()
      ScanViewpoint::Model model_ = ScanViewpoint::Model::perspective;
      /** Pushbroom: the depth at which v = y / z is scaled to a length (see retinal()). */
      float depth_scale_ = 1.0f;
      float u0_ = 0.0f, v0_ = 0.0f, inv_pixel_ = 1.0f;
      int width_ = 0, height_ = 0;
      std::vector<std::int32_t> triangle_;  ///< per pixel, row-major: index into planes_, or -1
      std::vector<std::uint8_t> empty_;     ///< per pixel: seen through (markEmptySpace()); empty before
      std::vector<Plane> planes_;
      /** Per tile of kTile x kTile pixels: smallest and largest surface depth (sensor z). */
      std::vector<float> tile_min_, tile_max_;
      int tiles_x_ = 0, tiles_y_ = 0;
  };
}
