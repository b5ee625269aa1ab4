/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/simulation/view_set.h>
#include <pcl/common/tensor_exceptions.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace pcl
{
  namespace
  {
    double
    radians (double deg)
    {
      return deg * M_PI / 180.0;
    }

    /** A right-handed frame (e1, e2, up) with up normalized; e1, e2 span the equator. */
    void
    equatorBasis (const Eigen::Vector3d& up, Eigen::Vector3d& e1, Eigen::Vector3d& e2, Eigen::Vector3d& n)
    {
      n = up.normalized ();
      const Eigen::Vector3d seed = std::abs (n.z ()) < 0.9 ? Eigen::Vector3d::UnitZ () : Eigen::Vector3d::UnitX ();
      e1 = (seed - seed.dot (n) * n).normalized ();
      e2 = n.cross (e1);
    }

    void
    appendRing (ViewDirections& out, int count, double step_deg, double elevation_deg, const Eigen::Vector3d& up)
    {
      Eigen::Vector3d e1, e2, n;
      equatorBasis (up, e1, e2, n);
      const double el = radians (elevation_deg);
      for (int k = 0; k < count; ++k)
      {
        const double az = radians (k * step_deg);
        out.push_back (std::cos (el) * (std::cos (az) * e1 + std::sin (az) * e2) + std::sin (el) * n);
      }
    }
  }

  ViewDirections
  makeDefaultViewDirections (const Eigen::Vector3d& up)
  {
    ViewDirections d;
    appendRing (d, 12, 30.0, 0.0, up);
    appendRing (d, 6, 60.0, 60.0, up);
    appendRing (d, 6, 60.0, -60.0, up);
    d.push_back (up.normalized ());
    d.push_back (-up.normalized ());
    return d;
  }

  ViewDirections
  makeRingViewDirections (int count, double step_deg, double elevation_deg, const Eigen::Vector3d& up)
  {
    if (count <= 0)
      PCL_TENSOR_THROW (pcl::BadArgumentException, "a ring needs at least one view, got " << count);
    if (!(std::abs (elevation_deg) < 90.0))
      PCL_TENSOR_THROW (pcl::BadArgumentException, "ring elevation must be in (-90, 90) degrees, got "
                        << elevation_deg);
    ViewDirections d;
    appendRing (d, count, step_deg, elevation_deg, up);
    return d;
  }

  ViewDirections
  makeRandomViewDirections (int count, std::uint32_t seed)
  {
    if (count < 0)
      PCL_TENSOR_THROW (pcl::BadArgumentException, "a view set cannot have " << count << " views");
    std::mt19937 rng (seed);
    std::normal_distribution<double> gauss;
    ViewDirections d;
    while (static_cast<int> (d.size ()) < count)
    {
      const Eigen::Vector3d v (gauss (rng), gauss (rng), gauss (rng));
      if (v.norm () > 1e-6)
        d.push_back (v.normalized ());
    }
    return d;
  }

  ViewTarget
  boundingTarget (const ScanMesh& mesh)
  {
    if (mesh.cloud->empty ())
      PCL_TENSOR_THROW (InvalidScanException, "boundingTarget: the mesh has no vertices");
    Eigen::Vector3d lo = Eigen::Vector3d::Constant (std::numeric_limits<double>::max ());
    Eigen::Vector3d hi = -lo;
    for (const auto& p : *mesh.cloud)
    {
      lo = lo.cwiseMin (p.getVector3fMap ().cast<double> ());
      hi = hi.cwiseMax (p.getVector3fMap ().cast<double> ());
    }
    ViewTarget t;
    t.centre = 0.5 * (lo + hi);
    for (const auto& p : *mesh.cloud)
      t.radius = std::max (t.radius, (p.getVector3fMap ().cast<double> () - t.centre).norm ());
    return t;
  }

  double
  fittingDistance (const ViewTarget& target, const RangeCameraParams& camera, double margin)
  {
    if (!(target.radius > 0.0) || !(margin >= 1.0))
      PCL_TENSOR_THROW (pcl::BadArgumentException, "fittingDistance: needs radius > 0 and margin >= 1, got "
                        << target.radius << " and " << margin);
    if (camera.orthographic)
      return 2.0 * target.radius * margin;
    // The vertical half-angle follows from the same focal length as the horizontal one.
    const double tan_h = std::tan (radians (0.5 * camera.fov_deg));
    const double tan_v = tan_h * camera.height / camera.width;
    const double half_angle = std::atan (std::min (tan_h, tan_v));
    return margin * target.radius / std::sin (half_angle);
  }

  double
  fittingOrthoExtent (const ViewTarget& target, const RangeCameraParams& camera, double margin)
  {
    if (!(target.radius > 0.0) || !(margin >= 1.0))
      PCL_TENSOR_THROW (pcl::BadArgumentException, "fittingOrthoExtent: needs radius > 0 and margin >= 1, got "
                        << target.radius << " and " << margin);
    // The extent is the image width; a taller-than-wide image already fits the sphere's height.
    const double aspect = std::max (1.0, static_cast<double> (camera.width) / camera.height);
    return 2.0 * target.radius * margin * aspect;
  }

  SensorPoses
  lookAtPoses (const ViewDirections& directions, const ViewTarget& target, double distance,
               const Eigen::Vector3d& up)
  {
    SensorPoses poses;
    poses.reserve (directions.size ());
    for (const auto& dir : directions)
    {
      const Eigen::Vector3d z = dir.normalized ();
      // At the poles any axis not parallel to the line of sight fixes the roll.
      const Eigen::Vector3d fallback = std::abs (z.x ()) < 0.9 ? Eigen::Vector3d::UnitX () : Eigen::Vector3d::UnitY ();
      const Eigen::Vector3d u = std::abs (z.dot (up.normalized ())) > 1.0 - 1e-9 ? fallback : up.normalized ();
      const Eigen::Vector3d x = u.cross (z).normalized ();
      const Eigen::Vector3d y = z.cross (x);
      Eigen::Matrix3d r;
      r << x, y, z;
      poses.push_back (Eigen::Translation3d (target.centre + distance * z) * r);
    }
    return poses;
  }

  std::vector<std::vector<int>>
  viewNeighbours (const ViewDirections& directions, double angle_deg, double tolerance_deg)
  {
    const int n = static_cast<int> (directions.size ());
    std::vector<std::vector<int>> out (n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
      {
        if (i == j)
          continue;
        const double c = std::clamp (directions[i].normalized ().dot (directions[j].normalized ()), -1.0, 1.0);
        if (std::abs (std::acos (c) * 180.0 / M_PI - angle_deg) <= tolerance_deg)
          out[i].push_back (j);
      }
    return out;
  }

  std::vector<std::pair<int, int>>
  adjacentViewPairs (const ViewDirections& directions, double angle_deg, double tolerance_deg)
  {
    const auto nb = viewNeighbours (directions, angle_deg, tolerance_deg);
    std::vector<std::pair<int, int>> pairs;
    for (int i = 0; i < static_cast<int> (nb.size ()); ++i)
      for (int j : nb[i])
        if (i < j)
          pairs.emplace_back (i, j);
    return pairs;
  }
}
