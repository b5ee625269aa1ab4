/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/simulation/scanner_artifacts.h>
#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace pcl
{
  namespace
  {
    using Cloud = pcl::PointCloud<pcl::PointXYZ>;

    void
    checkParams (const ScannerArtifactParams& p, const Cloud& cloud)
    {
      if (!(p.dropout_start_deg >= 0.0 && p.dropout_start_deg <= 90.0))
        PCL_TENSOR_THROW (BadArgumentException, "dropout must start between 0 and 90 degrees, got " << p.dropout_start_deg);
      if (p.holes < 0 || p.specks < 0 || !(p.hole_radius_pixels >= 0.0) || !std::isfinite (p.hole_radius_pixels) || p.speck_pixels < 1)
        PCL_TENSOR_THROW (BadArgumentException, "scanner artifacts need non-negative counts and hole radius, and specks of at least one pixel");
      if (!cloud.isOrganized ())
        PCL_TENSOR_THROW (BadArgumentException, "scanner artifacts need an organized rendering");
    }

    /** Make \a p a pixel without a return, as the renderer leaves one. */
    void
    clearPoint (pcl::PointXYZ& p)
    {
      p.x = p.y = p.z = std::numeric_limits<float>::quiet_NaN ();
    }

    bool
    finiteAt (const Cloud& cloud, int col, int row)
    {
      return col >= 0 && row >= 0 && col < static_cast<int> (cloud.width) && row < static_cast<int> (cloud.height) &&
             pcl::isXYZFinite (cloud.at (col, row));
    }

    /** The difference across a pixel along one image axis, one-sided at a border or a gap. */
    bool
    gridTangent (const Cloud& cloud, int col, int row, int dc, int dr, Eigen::Vector3f& tangent)
    {
      const bool ahead = finiteAt (cloud, col + dc, row + dr), behind = finiteAt (cloud, col - dc, row - dr);
      if (!ahead && !behind)
        return false;
      const Eigen::Vector3f a = ahead ? cloud.at (col + dc, row + dr).getVector3fMap () : cloud.at (col, row).getVector3fMap ();
      const Eigen::Vector3f b = behind ? cloud.at (col - dc, row - dr).getVector3fMap () : cloud.at (col, row).getVector3fMap ();
      tangent = a - b;
      return true;
    }

    /** |cos| of the angle between each surface pixel's grid normal and its line of sight; NaN where unknown. */
    std::vector<float>
    viewingCosines (const RenderedView& view)
    {
      const Cloud& cloud = *view.cloud;
      std::vector<float> cosines (cloud.size (), std::numeric_limits<float>::quiet_NaN ());
      for (int row = 0; row < static_cast<int> (cloud.height); ++row)
        for (int col = 0; col < static_cast<int> (cloud.width); ++col)
        {
          Eigen::Vector3f du, dv;
          if (!finiteAt (cloud, col, row) || !gridTangent (cloud, col, row, 1, 0, du) || !gridTangent (cloud, col, row, 0, 1, dv))
            continue;
          const Eigen::Vector3f n = du.cross (dv);
          if (n.squaredNorm () == 0.0f)
            continue;
          const Eigen::Vector3d p = cloud.at (col, row).getVector3fMap ().cast<double> ();
          const Eigen::Vector3f ray = view.viewpoint.towardSensor (p).cast<float> ();
          cosines[static_cast<std::size_t> (row) * cloud.width + col] = std::abs (n.normalized ().dot (ray));
        }
      return cosines;
    }

    void
    dropGrazing (RenderedView& view, double start_deg, std::mt19937& rng)
    {
      if (start_deg >= 90.0)
        return;
      const std::vector<float> cosines = viewingCosines (view);
      std::uniform_real_distribution<double> uniform (0.0, 1.0);
      for (std::size_t i = 0; i < cosines.size (); ++i)
      {
        if (std::isnan (cosines[i]))
          continue;
        const double angle = std::acos (std::min (1.0, static_cast<double> (cosines[i]))) * 180.0 / M_PI;
        const double p_drop = (angle - start_deg) / (90.0 - start_deg);
        // One draw per surface pixel whatever its angle, so that the pattern does not shift with the ramp.
        if (uniform (rng) < p_drop)
          clearPoint ((*view.cloud)[i]);
      }
    }

    /** Draws surface pixels (finite points) of a cloud, uniformly. */
    class SurfacePixels
    {
      public:
        explicit SurfacePixels (const Cloud& cloud)
        {
          for (std::size_t i = 0; i < cloud.size (); ++i)
            if (pcl::isXYZFinite (cloud[i]))
              pixels_.push_back (i);
        }

        bool empty () const { return pixels_.empty (); }

        std::size_t
        draw (std::mt19937& rng) const
        {
          return pixels_[std::uniform_int_distribution<std::size_t> (0, pixels_.size () - 1) (rng)];
        }

      private:
        std::vector<std::size_t> pixels_;
    };

    void
    punchHoles (RenderedView& view, const ScannerArtifactParams& params, std::mt19937& rng)
    {
      Cloud& cloud = *view.cloud;
      const SurfacePixels pixels (cloud);
      if (pixels.empty ())
        return;
      std::uniform_real_distribution<double> scale (0.5, 1.5);
      for (int h = 0; h < params.holes; ++h)
      {
        const std::size_t centre = pixels.draw (rng);
        const int cc = static_cast<int> (centre % cloud.width), cr = static_cast<int> (centre / cloud.width);
        const double radius = params.hole_radius_pixels * scale (rng);
        const int reach = static_cast<int> (std::ceil (radius));
        for (int row = std::max (0, cr - reach); row <= std::min (static_cast<int> (cloud.height) - 1, cr + reach); ++row)
          for (int col = std::max (0, cc - reach); col <= std::min (static_cast<int> (cloud.width) - 1, cc + reach); ++col)
            if ((col - cc) * (col - cc) + (row - cr) * (row - cr) <= radius * radius)
              clearPoint (cloud.at (col, row));
      }
    }

    /** \a p moved along its line of sight toward the sensor until its depth (along the sensor's axis)
      * is (1 - \a fraction) of what it was. */
    Eigen::Vector3d
    inFront (const ScanViewpoint& viewpoint, const Eigen::Vector3d& p, double fraction)
    {
      const Eigen::Matrix3d to_sensor = viewpoint.sensor_pose.linear ().transpose ();
      const double depth = (viewpoint.sensor_pose.inverse () * p).z ();
      const Eigen::Vector3d back = viewpoint.towardSensor (p);
      const double per_step = -(to_sensor * back).z ();  // depth lost per unit moved toward the sensor
      return per_step > 0.0 ? Eigen::Vector3d (p + (fraction * depth / per_step) * back) : p;
    }

    void
    addSpecks (RenderedView& view, const ScannerArtifactParams& params, std::mt19937& rng)
    {
      Cloud& cloud = *view.cloud;
      const SurfacePixels pixels (cloud);
      if (pixels.empty ())
        return;
      std::uniform_int_distribution<int> length (1, params.speck_pixels);
      std::uniform_real_distribution<double> lift (0.05, 0.5);
      // A pixel belongs to one speck at most: a second would move it twice.
      std::vector<bool> taken (cloud.size (), false);
      for (int s = 0; s < params.specks; ++s)
      {
        const std::size_t first = pixels.draw (rng);
        const int row = static_cast<int> (first / cloud.width), col0 = static_cast<int> (first % cloud.width);
        const int n = length (rng);
        const double fraction = lift (rng);
        for (int col = col0; col < std::min (col0 + n, static_cast<int> (cloud.width)); ++col)
        {
          const std::size_t i = static_cast<std::size_t> (row) * cloud.width + col;
          if (taken[i] || !finiteAt (cloud, col, row))
            continue;
          taken[i] = true;
          cloud[i].getVector3fMap () = inFront (view.viewpoint, cloud[i].getVector3fMap ().cast<double> (), fraction).cast<float> ();
        }
      }
    }
  }

  ScannerArtifactParams
  scannerLikeArtifacts ()
  {
    ScannerArtifactParams p;
    p.dropout_start_deg = 70.0;
    p.holes = 4;
    p.hole_radius_pixels = 4.0;
    p.specks = 20;
    p.speck_pixels = 3;
    return p;
  }

  void
  addScannerArtifacts (RenderedView& view, const ScannerArtifactParams& params, std::mt19937& rng)
  {
    checkParams (params, *view.cloud);
    dropGrazing (view, params.dropout_start_deg, rng);
    punchHoles (view, params, rng);
    addSpecks (view, params, rng);
    bool dense = true;
    for (const auto& p : *view.cloud)
      dense = dense && pcl::isXYZFinite (p);
    view.cloud->is_dense = dense;
  }
}
