/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/common/scan_viewpoint.h>

namespace pcl
{
  ScanViewpoint
  ScanViewpoint::fromPositiveZ ()
  {
    ScanViewpoint v;
    // Half a turn about x turns the sensor's +z (its line of sight) into the scan's -z.
    v.sensor_pose = Eigen::AngleAxisd (M_PI, Eigen::Vector3d::UnitX ());
    v.orthographic = true;
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

  Eigen::Vector3d
  ScanViewpoint::towardSensor (const Eigen::Vector3d& p) const
  {
    if (orthographic)
      return -sensor_pose.linear ().col (2);
    return (sensor_pose.translation () - p).normalized ();
  }

  Eigen::Vector2d
  ScanViewpoint::project (const Eigen::Vector3d& p) const
  {
    const Eigen::Vector3d s = sensor_pose.inverse () * p;
    if (orthographic)
      return s.head<2> ();
    return s.head<2> () / s.z ();
  }
}
