/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Geometry>

namespace pcl
{
  /** \brief Where a range scan was seen from: a perspective sensor at a point, an orthographic one
    * looking along a direction, or a pushbroom (line-scan) sensor whose lines of sight fan out from a
    * line. It orients normals toward the sensor and defines the retinal plane onto which unorganized
    * points are projected for Delaunay triangulation (Section 2).
    *
    * The sensor frame follows PCL's camera convention: the sensor looks along its own +z axis.
    * \ingroup common
    */
  struct ScanViewpoint
  {
    /** \brief How lines of sight run in the sensor frame. */
    enum class Model
    {
      /** From the origin through the point: retinal coordinates (x/z, y/z). */
      perspective,
      /** Parallel to +z: retinal coordinates (x, y). */
      orthographic,
      /** In the planes x = const, fanning out from the x axis (a laser stripe swept along x, as in
        * the Cyberware scanner of the Stanford scans): retinal coordinates (x, y/z). */
      pushbroom
    };

    /** \brief Sensor frame expressed in the scan frame, a rigid transform (columns: sensor axes; translation: origin). */
    Eigen::Affine3d sensor_pose = Eigen::Affine3d::Identity ();
    /** \brief How the lines of sight run. */
    Model model = Model::perspective;

    /** \brief The default for files that carry no sensor pose (PLY) and no grid a pushbroom explains
      * (fitPushbroomSensor): an orthographic sensor on the +z side of the scan, looking down -z.
      */
    static ScanViewpoint
    fromPositiveZ ();

    /** \brief A perspective sensor at the cloud's sensor_origin_, oriented by sensor_orientation_ (PCD). */
    template <typename PointT> static ScanViewpoint
    fromCloud (const pcl::PointCloud<PointT>& cloud)
    {
      ScanViewpoint v;
      v.sensor_pose = Eigen::Translation3d (cloud.sensor_origin_.template head<3> ().template cast<double> ())
                    * cloud.sensor_orientation_.template cast<double> ();
      return v;
    }

    /** \brief A perspective sensor at \a position looking at \a target. */
    static ScanViewpoint
    lookingAt (const Eigen::Vector3d& position, const Eigen::Vector3d& target);

    /** \brief A perspective sensor at \a position looking at the centroid of the finite points of
      * \a cloud: what a user means by "the scan was taken from there" (the apps' --viewpoint x,y,z).
      * \throw pcl::InvalidScanException when \a cloud has no finite point
      */
    static ScanViewpoint
    lookingAtScan (const Eigen::Vector3d& position, const pcl::PointCloud<pcl::PointXYZ>& cloud);

    /** \brief A pushbroom sensor whose lines of sight fan out from the line through \a axis_point along
      * \a axis_direction, looking toward \a target (which must lie off that line).
      */
    static ScanViewpoint
    pushbroom (const Eigen::Vector3d& axis_point, const Eigen::Vector3d& axis_direction, const Eigen::Vector3d& target);

    /** \brief True for a sensor at infinity (parallel lines of sight). */
    bool
    orthographic () const { return model == Model::orthographic; }

    /** \brief The unit vector from \a p toward the sensor. */
    Eigen::Vector3d
    towardSensor (const Eigen::Vector3d& p) const;

    /** \brief The projection of \a p onto the sensor's retinal plane (perspective: x/z, y/z in the
      * sensor frame; orthographic: x, y; pushbroom: x, y/z).
      */
    Eigen::Vector2d
    project (const Eigen::Vector3d& p) const;
  };
}
