/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/common/scan_viewpoint.h>
#include <pcl/common/tensor_exceptions.h>

#include <cmath>

namespace pcl
{
  ScanViewpoint
  ScanViewpoint::fromPositiveZ ()
  {
    ScanViewpoint v;
    // Half a turn about x turns the sensor's +z (its line of sight) into the scan's -z.
    v.sensor_pose = Eigen::AngleAxisd (M_PI, Eigen::Vector3d::UnitX ());
    v.model = Model::orthographic;
    return v;
  }

  ScanViewpoint
  ScanViewpoint::lookingAt (const Eigen::Vector3d& position, const Eigen::Vector3d& target)
  {
    const Eigen::Vector3d z = (target - position).normalized ();
    // Any up vector not parallel to the line of sight completes a right-handed frame.
    const Eigen::Vector3d up = std::abs (z.y ()) < 0.9 ? Eigen::Vector3d::UnitY () : Eigen::Vector3d::UnitX ();
    const Eigen::Vector3d x = up.cross (z).normalized ();
    const Eigen::Vector3d y = z.cross (x);
    Eigen::Matrix3d r;
    r << x, y, z;
    ScanViewpoint v;
    v.sensor_pose = Eigen::Translation3d (position) * r;
    return v;
  }

  ScanViewpoint
  ScanViewpoint::lookingAtScan (const Eigen::Vector3d& position, const pcl::PointCloud<pcl::PointXYZ>& cloud)
  {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero ();
    std::size_t n = 0;
    for (const auto& p : cloud)
      if (std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z))
      {
        centroid += p.getVector3fMap ().cast<double> ();
        ++n;
      }
    if (n == 0)
      PCL_TENSOR_THROW (pcl::InvalidScanException, "the scan has no finite point to look at");
    return lookingAt (position, centroid / static_cast<double> (n));
  }

  ScanViewpoint
  ScanViewpoint::pushbroom (const Eigen::Vector3d& axis_point, const Eigen::Vector3d& axis_direction,
                            const Eigen::Vector3d& target)
  {
    const Eigen::Vector3d x = axis_direction.normalized ();
    const Eigen::Vector3d offset = target - axis_point;
    const Eigen::Vector3d z = (offset - offset.dot (x) * x).normalized ();
    Eigen::Matrix3d r;
    r << x, z.cross (x), z;
    ScanViewpoint v;
    // The origin is the axis point nearest the target, so that sensor coordinates stay small.
    v.sensor_pose = Eigen::Translation3d (axis_point + offset.dot (x) * x) * r;
    v.model = Model::pushbroom;
    return v;
  }

  Eigen::Vector3d
  ScanViewpoint::towardSensor (const Eigen::Vector3d& p) const
  {
    switch (model)
    {
      case Model::orthographic:
        return -sensor_pose.linear ().col (2);
      case Model::pushbroom:
      {
        // Back to the axis within the point's own plane x = const: the offset from the sensor less
        // its part along the sweep axis (the pose is rigid, so no inverse is needed; this runs per vertex).
        const Eigen::Vector3d d = p - sensor_pose.translation ();
        const Eigen::Vector3d sweep = sensor_pose.linear ().col (0);
        return -(d - sweep * sweep.dot (d)).normalized ();
      }
      case Model::perspective:
        break;
    }
    return (sensor_pose.translation () - p).normalized ();
  }

  Eigen::Vector2d
  ScanViewpoint::project (const Eigen::Vector3d& p) const
  {
    const Eigen::Vector3d s = sensor_pose.inverse () * p;
    switch (model)
    {
      case Model::orthographic:
        return s.head<2> ();
      case Model::pushbroom:
        return Eigen::Vector2d (s.x (), s.y () / s.z ());
      case Model::perspective:
        break;
    }
    return s.head<2> () / s.z ();
  }
}
