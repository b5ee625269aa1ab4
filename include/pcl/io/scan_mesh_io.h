/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#pragma once

#include <pcl/common/scan_mesh.h>

#include <string>

namespace pcl
{
  namespace io
  {
    /** \brief Read a triangle mesh (PLY, read with pcl::io::loadPLYFile), such as a
      * Stanford reconstruction (bun_zipper.ply), into a ScanMesh.
      * \param[in] path the mesh file
      * \return the mesh; polygons with more than three vertices are fanned into triangles
      * \throw pcl::IOException when the file is missing or cannot be parsed
      * \throw InvalidScanException when it holds no triangle
      * \ingroup io
      */
    ScanMesh
    loadScanMesh (const std::string& path);

    /** \brief Write a ScanMesh as binary little-endian PLY: vertices with the fields of toPolygonMesh()
      * (x, y, z, normal_x, normal_y, normal_z, curvature, as float) and triangles as lists of int.
      * It reads back with loadScanMesh() or pcl::io::loadPLYFile. Unlike pcl::io::savePLYFileBinary,
      * it goes through no PCLPointCloud2 blob: a model is written from one buffer (doc/log.md), atomically
      * (writeFileAtomically()): a reader sees the old file or the new one, never part of one.
      * \throw pcl::IOException when the file cannot be written, or a polygon has over 255 vertices
      * \ingroup io
      */
    void
    saveScanMesh (const std::string& path, const ScanMesh& mesh);
  }
}
