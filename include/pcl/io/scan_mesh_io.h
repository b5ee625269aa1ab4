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
  }
}
