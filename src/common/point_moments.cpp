/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/common/point_moments.h>

namespace pcl
{
  PointMoments
  computePointMoments (const std::vector<Eigen::Vector3d>& points)
  {
    PointMoments m;
    if (points.empty ())
      return m;
    m.count = static_cast<double> (points.size ());
    for (const auto& p : points)
      m.mean += p;
    m.mean /= m.count;
    for (const auto& p : points)
      m.scatter.noalias () += (p - m.mean) * (p - m.mean).transpose ();
    return m;
  }

  PointMoments
  unitePointMoments (const PointMoments& a, const PointMoments& b, const Eigen::Affine3d& pose)
  {
    PointMoments u;
    u.count = a.count + b.count;
    if (!(u.count > 0.0))
      return u;
    const Eigen::Matrix3d& r = pose.linear ();
    const Eigen::Vector3d delta = pose * b.mean - a.mean;
    u.mean = a.mean + delta * (b.count / u.count);
    u.scatter = a.scatter + r * b.scatter * r.transpose () + delta * delta.transpose () * (a.count * b.count / u.count);
    return u;
  }
}
