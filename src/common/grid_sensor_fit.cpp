/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/common/grid_sensor_fit.h>
#include <pcl/common/point_tests.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <iterator>
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

    /** What the fit needs of one grid line: its finite points' count, sum and sum of outer products,
      * relative to a point of the scan (for precision). */
    struct Line
    {
      double n = 0.0;
      Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
      Eigen::Matrix3d outer = Eigen::Matrix3d::Zero ();

      void
      add (const Eigen::Vector3d& p)
      {
        n += 1.0;
        sum += p;
        outer += p * p.transpose ();
      }

      /** Scatter about \a c: sum of (p - c)(p - c)^T. */
      Eigen::Matrix3d
      scatterAbout (const Eigen::Vector3d& c) const
      {
        return outer - c * sum.transpose () - sum * c.transpose () + n * c * c.transpose ();
      }
    };

    /** The scan's grid lines, gathered in one pass: rows and columns, and each of them split into its
      * even and odd cells (a staggered sweep, like the Cyberware's whose odd rows sit half a column
      * over, keeps each half at one sweep position). */
    struct GridLines
    {
      /** The scan point the moments are taken relative to. */
      Eigen::Vector3d origin;
      std::vector<Line> rows, columns, row_halves, column_halves;
      /** Distances between consecutive finite points along the rows and along the columns. */
      std::vector<double> row_steps, column_steps;

      explicit GridLines (const pcl::PointCloud<pcl::PointXYZ>& cloud)
        : origin (firstFinite (cloud)), rows (cloud.height), columns (cloud.width), row_halves (2 * cloud.height),
          column_halves (2 * cloud.width)
      {
        std::vector<Eigen::Vector3d> above (cloud.width, Eigen::Vector3d::Zero ());
        std::vector<bool> has_above (cloud.width, false);
        for (std::size_t r = 0; r < cloud.height; ++r)
        {
          bool has_left = false;
          Eigen::Vector3d left = Eigen::Vector3d::Zero ();
          for (std::size_t c = 0; c < cloud.width; ++c)
          {
            const auto& point = cloud.at (c, r);
            if (!pcl::isXYZFinite (point))
              continue;
            const Eigen::Vector3d p = point.getVector3fMap ().cast<double> () - origin;
            rows[r].add (p), columns[c].add (p);
            row_halves[2 * r + c % 2].add (p), column_halves[2 * c + r % 2].add (p);
            if (has_left)
              row_steps.push_back ((p - left).norm ());
            if (has_above[c])
              column_steps.push_back ((p - above[c]).norm ());
            left = above[c] = p;
            has_left = true;
            has_above[c] = true;
          }
        }
      }

      static Eigen::Vector3d
      firstFinite (const pcl::PointCloud<pcl::PointXYZ>& cloud)
      {
        for (const auto& p : cloud)
          if (pcl::isXYZFinite (p))
            return p.getVector3fMap ().cast<double> ();
        return Eigen::Vector3d::Zero ();
      }
    };

    /** The lines with at least kMinLinePoints finite points. */
    std::vector<Line>
    longLines (const std::vector<Line>& lines)
    {
      std::vector<Line> out;
      std::copy_if (lines.begin (), lines.end (), std::back_inserter (out),
                    [] (const Line& l) { return l.n >= static_cast<double> (kMinLinePoints); });
      return out;
    }

    /** The sweep direction: the common normal of the planes x = const, one per swept line, each at
      * its own position, as the least eigenvector of the lines' pooled scatter; \a sum_sq gets the
      * squared residuals' sum. \return false when the lines do not define one normal */
    bool
    sweepDirection (const std::vector<Line>& lines, Eigen::Vector3d& direction, double& sum_sq)
    {
      Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero ();
      for (const auto& line : lines)
        scatter += line.scatterAbout (line.sum / line.n);
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (scatter);
      direction = solver.eigenvectors ().col (0);
      sum_sq = std::max (0.0, solver.eigenvalues () (0));
      return solver.eigenvalues () (1) > 0.0;
    }

    /** A line's moments on the plane across the sweep (basis rows e1, e2 of \a across). */
    struct Line2
    {
      double n = 0.0;
      Eigen::Vector2d sum;
      Eigen::Matrix2d outer;

      Line2 (const Line& line, const Eigen::Matrix<double, 2, 3>& across)
        : n (line.n), sum (across * line.sum), outer (across * line.outer * across.transpose ())
      {}

      Eigen::Matrix2d
      scatterAbout (const Eigen::Vector2d& c) const
      {
        return outer - c * sum.transpose () - sum * c.transpose () + n * c * c.transpose ();
      }
    };

    /** The unit normal of the 2D line through \a through that best fits \a line. */
    Eigen::Vector2d
    normalThrough (const Line2& line, const Eigen::Vector2d& through)
    {
      return Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> (line.scatterAbout (through)).eigenvectors ().col (0);
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
        a += lines[l].n * nn;
        b += nn * lines[l].sum;
      }
      const Eigen::Vector2d spread = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> (a, Eigen::EigenvaluesOnly).eigenvalues ();
      if (!(spread (0) > 1e-9 * spread (1)))
        return false;
      c = a.ldlt ().solve (b);
      return std::isfinite (c.x ()) && std::isfinite (c.y ());
    }

    /** In the plane across the sweep, every fanned line is a line through the axis point c. Starts
      * from each line's own fit, then alternates solving for c with refitting each line through c;
      * \a sum_sq gets the squared residuals' sum.
      * \return false when the lines are (nearly) parallel: the axis is at infinity */
    bool
    commonAxis (const std::vector<Line2>& lines, Eigen::Vector2d& c, double& sum_sq)
    {
      std::vector<Eigen::Vector2d> normal (lines.size ());
      for (std::size_t l = 0; l < lines.size (); ++l)
        normal[l] = normalThrough (lines[l], lines[l].sum / lines[l].n);
      for (int iteration = 0; iteration < kAxisIterations; ++iteration)
      {
        if (!nearestPoint (lines, normal, c))
          return false;
        for (std::size_t l = 0; l < lines.size (); ++l)
          normal[l] = normalThrough (lines[l], c);
      }
      sum_sq = 0.0;
      for (std::size_t l = 0; l < lines.size (); ++l)
        sum_sq += std::max (0.0, normal[l].dot (lines[l].scatterAbout (c) * normal[l]));
      return true;
    }

    /** The median of \a steps (which it reorders); 0 when empty. */
    double
    median (std::vector<double>& steps)
    {
      if (steps.empty ())
        return 0.0;
      std::nth_element (steps.begin (), steps.begin () + steps.size () / 2, steps.end ());
      return steps[steps.size () / 2];
    }

    double
    pointCount (const std::vector<Line>& lines)
    {
      double n = 0.0;
      for (const auto& line : lines)
        n += line.n;
      return n;
    }

    /** One assignment: \a fanned lines in planes through the axis, \a swept lines at one sweep
      * position each. */
    GridSensorFit
    fitAssignment (const std::vector<Line>& fanned, const std::vector<Line>& swept, double spacing,
                   const Eigen::Vector3d& origin)
    {
      GridSensorFit fit;
      fit.fan_rms = fit.sweep_rms = std::numeric_limits<double>::infinity ();
      Eigen::Vector3d sweep;
      double sweep_sq = 0.0;
      if (fanned.size () < 3 || swept.size () < 3 || !(spacing > 0.0) || !sweepDirection (swept, sweep, sweep_sq))
        return fit;
      const Eigen::Vector3d e1 = sweep.unitOrthogonal (), e2 = sweep.cross (e1);
      Eigen::Matrix<double, 2, 3> across;
      across << e1.transpose (), e2.transpose ();
      std::vector<Line2> lines;
      Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
      for (const auto& line : fanned)
      {
        lines.emplace_back (line, across);
        sum += line.sum;
      }
      Eigen::Vector2d axis;
      double fan_sq = 0.0;
      if (!commonAxis (lines, axis, fan_sq))
        return fit;
      fit.fan_rms = std::sqrt (fan_sq / pointCount (fanned)) / spacing;
      fit.sweep_rms = std::sqrt (sweep_sq / pointCount (swept)) / spacing;
      fit.viewpoint = ScanViewpoint::pushbroom (origin + axis.x () * e1 + axis.y () * e2, sweep,
                                                origin + sum / pointCount (fanned));
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
    GridLines grid (cloud);
    const double spacing = std::min (median (grid.row_steps), median (grid.column_steps));
    const std::vector<Line> rows = longLines (grid.rows), columns = longLines (grid.columns);
    for (const bool rows_fanned : {true, false})
    {
      const GridSensorFit fit = rows_fanned ? fitAssignment (rows, longLines (grid.column_halves), spacing, grid.origin)
                                            : fitAssignment (columns, longLines (grid.row_halves), spacing, grid.origin);
      if (fit.fan_rms < best.fan_rms)
        best = fit;
    }
    best.found = best.fan_rms <= fan_tolerance && best.sweep_rms <= sweep_tolerance;
    return best;
  }
}
