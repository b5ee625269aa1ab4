/*
 * pcl_tensor: 2D Delaunay triangulation of the retinal plane (private to the library).
 */
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace pcl
{
  namespace detail
  {
    /** \brief The Delaunay triangulation of \a points: a sweep from the centre outward that adds each
      * point to the convex hull of those before it and restores the empty-circle property by edge flips
      * (Agafonkin's Delaunator, after Sinclair's s-hull), in O(n log n) and flat arrays: a range scan's
      * tens of thousands of points take milliseconds, not the seconds of vtkDelaunay2D
      * (doc/design.md#delaunay-gap-triangles). A point that repeats one already placed (within
      * rounding) is left out, and collinear points give no triangle.
      * \return triangles as indices into \a points, each counter-clockwise (positive signed area)
      */
    std::vector<std::array<std::int32_t, 3>>
    delaunayTriangulation (const std::vector<Eigen::Vector2d>& points);
  }
}
