/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/registration/global_verification.h>
#include <pcl/common/tensor_exceptions.h>

#include "../common/convex_hull_vertices.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <functional>
#include <limits>

namespace pcl
{
  namespace registration
  {
    namespace
    {
      /** Running lowest and highest projections of points along three axes. */
      struct Span
      {
        Eigen::Vector3d low = Eigen::Vector3d::Constant (std::numeric_limits<double>::infinity ());
        Eigen::Vector3d high = -Eigen::Vector3d::Constant (std::numeric_limits<double>::infinity ());

        /** Widen by \a points mapped by q = linear * p + offset. */
        void
        add (const std::vector<Eigen::Vector3f>& points, const Eigen::Matrix3d& linear, const Eigen::Vector3d& offset)
        {
          for (const auto& p : points)
          {
            const Eigen::Vector3d q = linear * p.cast<double> () + offset;
            low = low.cwiseMin (q);
            high = high.cwiseMax (q);
          }
        }

        /** Extents sorted from largest to smallest (zero when empty). */
        Eigen::Vector3d
        extents () const
        {
          Eigen::Vector3d e = (high - low).cwiseMax (0.0);
          if (!e.allFinite ())
            e.setZero ();
          std::sort (e.data (), e.data () + 3, std::greater<> ());
          return e;
        }
      };
    }

    GlobalVerification::GlobalVerification (const ObjectDimensions& dims, double resolution, const GlobalVerificationParams& params)
      : dims_ (dims), resolution_ (resolution), params_ (params)
    {
      if (!(resolution > 0.0) || !(params.tolerance >= 0.0))
        PCL_TENSOR_THROW (BadArgumentException, "global verification needs a positive resolution and a non-negative tolerance");
    }

    namespace
    {
      /** The vertices of the convex hull of \a points (relative coordinates): extents along any axes are
        * taken at them, so a group keeps a few hundred points per view instead of all of them. All
        * points when the hull cannot be made: fewer than four, or \a flat (all in a plane). */
      std::vector<Eigen::Vector3f>
      hullVertices (const std::vector<Eigen::Vector3f>& points, bool flat)
      {
        if (points.size () < 4 || flat)
          return points;
        std::vector<Eigen::Vector3f> vertices = detail::convexHullVertices (points);
        return vertices.size () < 4 ? points : vertices;
      }
    }

    GlobalVerification
    GlobalVerification::single (const pcl::PointCloud<pcl::PointNormal>& cloud) const
    {
      GlobalVerification view (dims_, resolution_, params_);
      std::vector<Eigen::Vector3d> points;
      points.reserve (cloud.size ());
      for (const auto& p : cloud)
        if (p.getVector3fMap ().allFinite ())
          points.push_back (p.getVector3fMap ().cast<double> ());
      view.moments_ = computePointMoments (points);
      const PointMoments& m = view.moments_;
      Frame frame;
      if (!points.empty ())
      {
        view.anchor_ = points.front ();
        view.anchored_ = true;
        std::vector<Eigen::Vector3f> relative;
        relative.reserve (points.size ());
        for (const auto& p : points)
          relative.push_back ((p - view.anchor_).cast<float> ());
        const Eigen::Vector3d spread = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> (m.scatter).eigenvalues ();
        view.points_ = hullVertices (relative, !(spread.minCoeff () > 1e-12 * spread.maxCoeff ()));
      }
      if (points.size () >= 3)
      {
        frame.valid = true;
        frame.axes = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> (m.scatter).eigenvectors ();
        Span span;
        span.add (view.points_, frame.axes.transpose (), Eigen::Vector3d::Zero ());
        frame.low = span.low;
        frame.high = span.high;
      }
      view.frames_.push_back (frame);
      return view;
    }

    Eigen::Vector3d
    GlobalVerification::unionExtents (const GlobalVerification& other, const Eigen::Affine3d& pose, const Eigen::Matrix3d& axes) const
    {
      const Eigen::Vector3d anchor = anchored_ ? anchor_ : pose * other.anchor_;
      Span span;
      span.add (points_, axes.transpose (), Eigen::Vector3d::Zero ());
      span.add (other.points_, axes.transpose () * pose.linear (), axes.transpose () * (pose * other.anchor_ - anchor));
      return span.extents ();
    }

    GlobalVerification::Frame
    GlobalVerification::movedFrame (const Frame& frame, const GlobalVerification& other, const Eigen::Affine3d& pose) const
    {
      // a' = R a; a'^T (R p + t - anchor) = a^T (p - other.anchor) + a^T other.anchor + a'^T (t - anchor).
      const Eigen::Vector3d anchor = anchored_ ? anchor_ : pose * other.anchor_;
      Frame moved = frame;
      moved.axes = pose.linear () * frame.axes;
      const Eigen::Vector3d shift = frame.axes.transpose () * other.anchor_ + moved.axes.transpose () * (pose.translation () - anchor);
      moved.low += shift;
      moved.high += shift;
      return moved;
    }

    double
    GlobalVerification::excess (const GlobalVerification& other, const Eigen::Affine3d& pose) const
    {
      // The union's moments: the other group's moved, then combined (Chan et al.'s pairwise update).
      const PointMoments both = unitePointMoments (moments_, other.moments_, pose);
      if (both.count < 3.0)
        PCL_TENSOR_THROW (InvalidScanException, "principal axes need at least 3 finite points, got " << both.count);
      const Eigen::Matrix3d& r = pose.linear ();
      const Eigen::Matrix3d axes = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> (both.scatter).eigenvectors ();
      const int checked = params_.checked_dimensions;
      double excess = dimensionExcess (unionExtents (other, pose, axes), dims_, checked);

      // Each view's own frame: its extents so far, widened by the points of the other group.
      const Eigen::Vector3d anchor = anchored_ ? anchor_ : pose * other.anchor_;
      for (const Frame& f : frames_)
        if (f.valid)
        {
          Span span{f.low, f.high};
          span.add (other.points_, f.axes.transpose () * r, f.axes.transpose () * (pose * other.anchor_ - anchor));
          excess = std::min (excess, dimensionExcess (span.extents (), dims_, checked));
        }
      for (const Frame& g : other.frames_)
        if (g.valid)
        {
          const Frame moved = movedFrame (g, other, pose);
          Span span{moved.low, moved.high};
          span.add (points_, moved.axes.transpose (), Eigen::Vector3d::Zero ());
          excess = std::min (excess, dimensionExcess (span.extents (), dims_, checked));
        }
      return excess / resolution_;
    }

    double
    GlobalVerification::excess (const pcl::PointCloud<pcl::PointNormal>& cloud, const Eigen::Affine3d& pose) const
    {
      return excess (single (cloud), pose);
    }

    void
    GlobalVerification::merge (const GlobalVerification& other, const Eigen::Affine3d& pose)
    {
      if (!anchored_ && other.anchored_)
      {
        anchor_ = pose * other.anchor_;
        anchored_ = true;
      }
      const Eigen::Matrix3d& r = pose.linear ();
      for (Frame& f : frames_)
        if (f.valid)
        {
          Span span{f.low, f.high};
          span.add (other.points_, f.axes.transpose () * r, f.axes.transpose () * (pose * other.anchor_ - anchor_));
          f.low = span.low;
          f.high = span.high;
        }
      for (const Frame& g : other.frames_)
      {
        Frame moved = g.valid ? movedFrame (g, other, pose) : g;
        if (moved.valid)
        {
          Span span{moved.low, moved.high};
          span.add (points_, moved.axes.transpose (), Eigen::Vector3d::Zero ());
          moved.low = span.low;
          moved.high = span.high;
        }
        frames_.push_back (moved);
      }
      if (other.moments_.count > 0.0)
        moments_ = unitePointMoments (moments_, other.moments_, pose);
      points_.reserve (points_.size () + other.points_.size ());
      const Eigen::Vector3d offset = pose * other.anchor_ - anchor_;
      for (const auto& p : other.points_)
        points_.push_back ((r * p.cast<double> () + offset).cast<float> ());
    }

    void
    GlobalVerification::addView (const pcl::PointCloud<pcl::PointNormal>& cloud, const Eigen::Affine3d& pose)
    {
      merge (single (cloud), pose);
    }
  }
}
