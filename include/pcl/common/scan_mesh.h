/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_viewpoint.h>
#include <pcl/PolygonMesh.h>
#include <pcl/Vertices.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <vector>

namespace pcl
{
  /** \brief A triangle mesh of one range scan: M_i (fine) or M'_i (reduced) in the paper's notation.
    *
    * Unlike pcl::PolygonMesh, whose vertices sit in a binary blob, the vertices are a typed cloud so
    * that algorithms can read them directly. Every polygon is a triangle of indices into \a cloud;
    * the cloud holds no NaN. Normals are zero until a normal estimator fills them in.
    * \ingroup common
    */
  struct ScanMesh
  {
    using Ptr = shared_ptr<ScanMesh>;
    using ConstPtr = shared_ptr<const ScanMesh>;

    /** \brief Vertices, with their normals once estimated. Never null. */
    pcl::PointCloud<pcl::PointNormal>::Ptr cloud{new pcl::PointCloud<pcl::PointNormal>};
    /** \brief Triangles, as indices into \a cloud. */
    std::vector<pcl::Vertices> polygons;
    /** \brief Where the scan was seen from; normals are oriented toward it. */
    ScanViewpoint viewpoint;
  };

  /** \brief Mesh resolution d_res: the mean length of the mesh's distinct edges (Section 2, Eq. 12). */
  double
  meshResolution (const ScanMesh& mesh);

  /** \brief Which vertices lie on the mesh's boundary: on an edge that only one triangle uses. */
  std::vector<bool>
  meshBoundaryVertices (const ScanMesh& mesh);

  /** \brief Total surface area of the mesh's triangles. */
  double
  meshArea (const ScanMesh& mesh);

  /** \brief Convert to pcl::PolygonMesh (fields x, y, z, normal_x, normal_y, normal_z, curvature). */
  void
  toPolygonMesh (const ScanMesh& mesh, pcl::PolygonMesh& out);

  /** \brief Convert from pcl::PolygonMesh; polygons with more than three vertices are fanned into
    * triangles. Normals are taken from the blob when it has them.
    * \throw InvalidScanException when the mesh has faces but no vertices, or indices out of range.
    */
  void
  fromPolygonMesh (const pcl::PolygonMesh& in, ScanMesh& out);
}
