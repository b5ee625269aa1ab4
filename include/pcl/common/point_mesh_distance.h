/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_mesh.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Core>

#include <memory>
#include <vector>

namespace pcl
{
  /** \brief Exact Euclidean distance from a point to a triangle (closest point by Voronoi regions).
    * \param[in] p the point
    * \param[in] a, b, c the triangle's corners
    * \return the distance from \a p to the closest point of the triangle
    * \ingroup common
    */
  double
  pointTriangleDistance (const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c);

  /** \brief Exact distance from points to a triangle mesh, e.g. to check that a rendered or registered
    * view lies on its model.
    *
    * The closest triangle is never farther than the nearest vertex (distance d_v), so only triangles
    * whose centroid lies within d_v + (largest centroid-to-vertex distance) can hold the closest point;
    * those are found with kd-trees and measured exactly. The answer is therefore exact, not an
    * approximation by the nearest vertex.
    * \ingroup common
    */
  class PointMeshDistance
  {
    public:
      using Ptr = shared_ptr<PointMeshDistance>;
      using ConstPtr = shared_ptr<const PointMeshDistance>;

      /** \brief An empty index; call setMesh() before distance(). */
      PointMeshDistance ();
      ~PointMeshDistance ();

      /** \brief Index the mesh's triangles.
        * \throw InvalidScanException when the mesh has no triangle, or a polygon is not a valid triangle
        */
      void setMesh (const ScanMesh& mesh);

      /** \brief The distance from \a p to the closest point of the mesh.
        * \throw InvalidScanException when no mesh was set
        */
      double distance (const Eigen::Vector3d& p) const;

    private:
      struct Index;
      std::unique_ptr<Index> index_;
  };
}
