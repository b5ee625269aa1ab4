/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include "convex_hull_vertices.h"

extern "C"
{
#include <libqhull_r/qhull_ra.h>
}

#include <cstdlib>

namespace pcl
{
  namespace detail
  {
    std::vector<Eigen::Vector3f>
    convexHullVertices (const std::vector<Eigen::Vector3f>& points)
    {
      std::vector<Eigen::Vector3f> vertices;
      if (points.size () < 4)
        return vertices;
      constexpr int dimension = 3;
      // qhull frees the coordinates itself (ismalloc), so they come from calloc.
      auto* coords = static_cast<coordT*> (std::calloc (points.size () * dimension, sizeof (coordT)));
      if (!coords)
        return vertices;
      for (std::size_t i = 0; i < points.size (); ++i)
        for (int k = 0; k < dimension; ++k)
          coords[i * dimension + k] = static_cast<coordT> (points[i][k]);
      qhT qh_qh;
      qhT* qh = &qh_qh;
      qh_zero (qh, stderr);
      char flags[] = "qhull ";  // pcl::ConvexHull's options without the area
      const int exitcode = qh_new_qhull (qh, dimension, static_cast<int> (points.size ()), coords, True, flags,
                                         nullptr, stderr);
      if (exitcode == 0)
      {
        vertices.reserve (static_cast<std::size_t> (qh->num_vertices));
        vertexT* vertex;
        FORALLvertices
          vertices.push_back (points[static_cast<std::size_t> (qh_pointid (qh, vertex->point))]);
      }
      qh_freeqhull (qh, !qh_ALL);
      int curlong = 0, totlong = 0;
      qh_memfreeshort (qh, &curlong, &totlong);
      return vertices;
    }
  }
}
