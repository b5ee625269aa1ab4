/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/common/grid_sensor_fit.h>
#include <pcl/common/point_tests.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace pcl
{
  namespace
  {
    /** Grid lines with fewer finite points say too little about their plane. */
    constexpr std::size_t kMinLinePoints = 10;
    /** Alternations between the axis and the planes through it; the fit settles within a few. */
    constexpr int kAxisIterations = 4;

    using Line = std::vector<Eigen::Vector3d>;

    /** The finite points of each row (by_rows) or each column, keeping lines of kMinLinePoints or more.
      * With \a by_parity each line's even and odd cells become two lines: a staggered sweep (the
      * Cyberware's odd rows sit half a column over) keeps each half at one sweep position. */
    std::vector<Line>
    gridLines (const pcl::PointCloud<pcl::PointXYZ>& cloud, bool by_rows, bool by_parity)
    {
      const std::size_t lines = by_rows ? cloud.height : cloud.width, length = by_rows ? cloud.width : cloud.height;
      const std::size_t step = by_parity ? 2 : 1;
      std::vector<Line> out;
      for (std::size_t l = 0; l < lines; ++l)
        for (std::size_t first = 0; first < step; ++first)
        {
          Line line;
          for (std::size_t k = first; k < length; k += step)
          {
            const auto& p = by_rows ? cloud.at (k, l) : cloud.at (l, k);
            if (pcl::isXYZFinite (p))
              line.push_back (p.getVector3fMap ().cast<double> ());
          }
          if (line.size () >= kMinLinePoints)
            out.push_back (std::move (line));
        }
      return out;
    }

    Eigen::Vector3d
    centroid (const Line& line)
    {
      Eigen::Vector3d c = Eigen::Vector3d::Zero ();
      for (const auto& p : line)
        c += p;
      return c / static_cast<double> (line.size ());
    }

    /** The sweep direction: the common normal of the planes x = const, one per swept line, each at
      * its own position, as the least eigenvector of the lines' pooled scatter; \a sum_sq gets the
      * squared residuals' sum. \return false when the lines do not define one normal */
    bool
    sweepDirection (const std::vector<Line>& lines, Eigen::Vector3d& direction, double& sum_sq)
    {
      Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero ();
      for (const auto& line : lines)
      {
        const Eigen::Vector3d c = centroid (line);
        for (const auto& p : line)
          scatter += (p - c) * (p - c).transpose ();
      }
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (scatter);
      direction = solver.eigenvectors ().col (0);
      sum_sq = std::max (0.0, solver.eigenvalues () (0));
      return solver.eigenvalues () (1) > 0.0;
    }

    using Line2 = std::vector<Eigen::Vector2d>;

    /** The unit normal of the 2D line through \a through that best fits \a line. */
    Eigen::Vector2d
    normalThrough (const Line2& line, const Eigen::Vector2d& through)
    {
      Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero ();
      for (const auto& q : line)
        scatter += (q - through) * (q - through).transpose ();
      return Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> (scatter).eigenvectors ().col (0);
    }

    /** The point nearest every line (given by its normal) over all their points, in least squares:
      * sum over the points of n n^T (q - c) = 0. \return false when the lines are (nearly) parallel */
    bool
    nearestPoint (const std::vector<Line2>& lines, const std::vector<Eigen::Vector2d>& normal, Eigen::Vector2d& c)
    {
      Eigen::Matrix2d a = Eigen::Matrix2d::Zero ();
      Eigen::Vector2d b = Eigen::Vector2d::Zero ();
      for (std::size_t l = 0; l < lines.size (); ++l)
      {
        const Eigen::Matrix2d nn = normal[l] * normal[l].transpose ();
        for (const auto& q : lines[l])
        {
          a += nn;
          b += nn * q;
        }
      }
      const Eigen::Vector2d spread = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> (a, Eigen::EigenvaluesOnly).eigenvalues ();
      if (!(spread (0) > 1e-9 * spread (1)))
        return false;
      c = a.ldlt ().solve (b);
      return std::isfinite (c.x ()) && std::isfinite (c.y ());
    }

    /** In the plane across the sweep (basis e1, e2), every fanned line is a line through the axis
      * point c. Starts from each line's own fit, then alternates solving for c with refitting each
      * line through c; \a sum_sq gets the squared residuals' sum.
      * \return false when the lines are (nearly) parallel: the axis is at infinity */
    bool
    commonAxis (const std::vector<Line2>& lines, Eigen::Vector2d& c, double& sum_sq)
    {
      std::vector<Eigen::Vector2d> normal (lines.size ());
      for (std::size_t l = 0; l < lines.size (); ++l)
      {
        Eigen::Vector2d mean = Eigen::Vector2d::Zero ();
        for (const auto& q : lines[l])
          mean += q;
        normal[l] = normalThrough (lines[l], mean / static_cast<double> (lines[l].size ()));
      }
      for (int iteration = 0; iteration < kAxisIterations; ++iteration)
      {
        if (!nearestPoint (lines, normal, c))
          return false;
        for (std::size_t l = 0; l < lines.size (); ++l)
          normal[l] = normalThrough (lines[l], c);
      }
      sum_sq = 0.0;
      for (std::size_t l = 0; l < lines.size (); ++l)
        for (const auto& q : lines[l])
          sum_sq += std::pow (normal[l].dot (q - c), 2);
      return true;
    }

    /** Median distance between grid neighbours along the lines: the scale of fan_rms and sweep_rms. */
    double
    medianSpacing (const std::vector<Line>& lines)
    {
      std::vector<double> steps;
      for (const auto& line : lines)
        for (std::size_t k = 1; k < line.size (); ++k)
          steps.push_back ((line[k] - line[k - 1]).norm ());
      if (steps.empty ())
        return 0.0;
      std::nth_element (steps.begin (), steps.begin () + steps.size () / 2, steps.end ());
      return steps[steps.size () / 2];
    }

    std::size_t
    pointCount (const std::vector<Line>& lines)
    {
      std::size_t n = 0;
      for (const auto& line : lines)
        n += line.size ();
      return n;
    }

    /** One assignment: \a fanned lines in planes through the axis, \a swept lines at one sweep
      * position each. */
    GridSensorFit
    fitAssignment (const std::vector<Line>& fanned, const std::vector<Line>& swept, double spacing)
    {
      GridSensorFit fit;
      fit.fan_rms = fit.sweep_rms = std::numeric_limits<double>::infinity ();
      Eigen::Vector3d sweep;
      double sweep_sq = 0.0;
      if (fanned.size () < 3 || swept.size () < 3 || !(spacing > 0.0) || !sweepDirection (swept, sweep, sweep_sq))
        return fit;
      const Eigen::Vector3d e1 = sweep.unitOrthogonal (), e2 = sweep.cross (e1);
      std::vector<Line2> across (fanned.size ());
      Eigen::Vector3d mean = Eigen::Vector3d::Zero ();
      for (std::size_t l = 0; l < fanned.size (); ++l)
        for (const auto& p : fanned[l])
        {
          across[l].emplace_back (p.dot (e1), p.dot (e2));
          mean += p;
        }
      Eigen::Vector2d axis;
      double fan_sq = 0.0;
      if (!commonAxis (across, axis, fan_sq))
        return fit;
      fit.fan_rms = std::sqrt (fan_sq / static_cast<double> (pointCount (fanned))) / spacing;
      fit.sweep_rms = std::sqrt (sweep_sq / static_cast<double> (pointCount (swept))) / spacing;
      fit.viewpoint = ScanViewpoint::pushbroom (axis.x () * e1 + axis.y () * e2, sweep,
                                                mean / static_cast<double> (pointCount (fanned)));
      return fit;
    }
  }

  GridSensorFit
  fitPushbroomSensor (const pcl::PointCloud<pcl::PointXYZ>& cloud, double fan_tolerance, double sweep_tolerance)
  {
    GridSensorFit best;
    best.fan_rms = best.sweep_rms = std::numeric_limits<double>::infinity ();
    if (!cloud.isOrganized () || cloud.width < kMinLinePoints || cloud.height < kMinLinePoints)
      return best;
    const std::vector<Line> rows = gridLines (cloud, true, false), columns = gridLines (cloud, false, false);
    const double spacing = std::min (medianSpacing (rows), medianSpacing (columns));
    for (const bool rows_fanned : {true, false})
    {
      const GridSensorFit fit = rows_fanned ? fitAssignment (rows, gridLines (cloud, false, true), spacing)
                                            : fitAssignment (columns, gridLines (cloud, true, true), spacing);
      if (fit.fan_rms < best.fan_rms)
        best = fit;
    }
    best.found = best.fan_rms <= fan_tolerance && best.sweep_rms <= sweep_tolerance;
    return best;
  }
}
