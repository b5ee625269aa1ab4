/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 *
 * Private to the library: the vertices of a 3D convex hull, from qhull directly.
 */
#pragma once

#include <Eigen/Core>

#include <vector>

namespace pcl
{
  namespace detail
  {
    /** The vertices of the convex hull of \a points, as pcl::ConvexHull<PointXYZ> finds them (qhull with
      * the same options), in qhull's order. Calling qhull directly keeps libpcl_surface, and the VTK
      * libraries it loads (about 27 ms per process), out of the tools that need only this.
      * \return empty when qhull cannot make the hull (fewer than four points, all in a plane) */
    std::vector<Eigen::Vector3f>
    convexHullVertices (const std::vector<Eigen::Vector3f>& points);
  }
}
