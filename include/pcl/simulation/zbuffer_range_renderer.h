/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_mesh.h>
#include <pcl/common/scan_viewpoint.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Geometry>

#include <vector>

namespace pcl
{
  /** \brief A synthetic range camera. Its frame looks along its own -z axis (OpenGL / Stanford
    * convention: visible points have z < 0), x to the right of the image and y up; row 0 of the image
    * is the top row.
    * \ingroup simulation
    */
  struct RangeCameraParams
  {
    /** Image width in pixels (columns). */
    int width = 400;
    /** Image height in pixels (rows). */
    int height = 400;
    /** Horizontal field of view of the perspective camera, in degrees (0 < fov < 180). */
    double fov_deg = 40.0;
    /** True for an orthographic camera (parallel rays along -z, starting on the plane z = 0). */
    bool orthographic = false;
    /** True for a pushbroom (line-scan) camera, as laser stripe scanners sweep: each column is a fan
      * of rays in its own plane x = const, from a sensor line along x (columns ortho_extent / width
      * apart, the fan's focal length that of fov_deg over the width). Not with orthographic. */
    bool pushbroom = false;
    /** Width of the orthographic camera's field, or the pushbroom's sweep, in metres. */
    double ortho_extent = 0.3;
  };

  /** \brief One synthetic range image and its exact ground truth.
    * \ingroup simulation
    */
  struct RenderedView
  {
    /** \brief Organized width x height cloud in the sensor frame; NaN where no surface was hit. */
    pcl::PointCloud<pcl::PointXYZ>::Ptr cloud{new pcl::PointCloud<pcl::PointXYZ>};
    /** \brief Ground truth: maps sensor-frame points into the model frame (p_model = pose * p). */
    Eigen::Affine3d pose = Eigen::Affine3d::Identity ();
    /** \brief The sensor as seen from its own frame (origin, looking down -z), to orient normals. */
    ScanViewpoint viewpoint;
  };

  /** \brief A pixel's line of sight in the sensor frame: origin + t * direction, t > 0.
    * \ingroup simulation
    */
  struct PixelRay
  {
    /** Perspective: the sensor's centre (0, 0, 0); orthographic: the pixel centre on the plane z = 0;
      * pushbroom: the column's point on the sensor line (x, 0, 0). */
    Eigen::Vector3d origin = Eigen::Vector3d::Zero ();
    /** Not normalized: the perspective and pushbroom directions have z = -1 (a pushbroom's x = 0), the
      * orthographic one is (0, 0, -1). */
    Eigen::Vector3d direction = -Eigen::Vector3d::UnitZ ();
  };

  /** \brief Z-buffer renderer of a triangle mesh into range images with exact ground truth, as used
    * to make the 26 synthetic views of Section 6 and Section 7.1.
    *
    * Each triangle is projected, and every pixel centre inside its projected bounding box (grown by
    * one pixel) is tested by an exact double-precision ray/triangle intersection; the nearest hit wins.
    * A rendered point is therefore the intersection of its pixel's ray with the mesh, not an
    * interpolated depth, and lies on the mesh up to float rounding of the output.
    * \ingroup simulation
    */
  class ZBufferRangeRenderer
  {
    public:
      using Ptr = shared_ptr<ZBufferRangeRenderer>;
      using ConstPtr = shared_ptr<const ZBufferRangeRenderer>;

      /** \brief Set the mesh to render (its vertices and triangles; normals are ignored).
        * \param[in] mesh the model; its triangles are copied in double precision
        * \throw InvalidScanException when it has no triangles, or a triangle indexes a missing or
        * non-finite vertex
        */
      void setMesh (const ScanMesh& mesh);

      /** \brief Set the camera (default: RangeCameraParams{}).
        * \throw pcl::BadArgumentException on a non-positive size, a fov outside (0, 180) degrees or a
        * non-positive orthographic extent
        */
      void setCameraParams (const RangeCameraParams& params);
      /** \brief The camera in use. */
      const RangeCameraParams& getCameraParams () const { return params_; }

      /** \brief Render the mesh seen by a sensor placed at \a sensor_pose.
        * \param[in] sensor_pose the sensor frame expressed in the model frame (maps sensor-frame points
        * into the model frame); it becomes the returned view's ground truth
        * \return the organized range image in the sensor frame, and its ground truth
        * \throw InvalidScanException when no mesh was set
        */
      RenderedView render (const Eigen::Affine3d& sensor_pose) const;

      /** \brief The ray of pixel (\a col, \a row) in the sensor frame, through the pixel centre.
        * \param[in] col column, 0 at the left of the image
        * \param[in] row row, 0 at the top of the image
        * \return the ray; its hit point origin + t * direction is what render() stores in that cell
        */
      PixelRay pixelRay (int col, int row) const;

    private:
      struct Triangle
      {
        Eigen::Vector3d a, b, c;
      };

      /** Pixel-space bounding box of a sensor-frame triangle; false if it cannot cover any pixel. */
      bool pixelBounds (const Triangle& t, int& c0, int& c1, int& r0, int& r1) const;

      std::vector<Triangle> triangles_;
      RangeCameraParams params_;
  };

  /** \brief Möller–Trumbore intersection of the ray origin + t * direction with a triangle, in double.
    * \param[in] origin, direction the ray
    * \param[in] a, b, c the triangle's corners
    * \param[out] t the ray parameter of the hit
    * \return true when the ray hits the triangle (edges included) at t > 0
    * \ingroup simulation
    */
  bool
  intersectRayTriangle (const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                        const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                        double& t);
}
