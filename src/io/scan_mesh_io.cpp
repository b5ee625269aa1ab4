/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/scan_mesh_io.h>
#include "file_input.h"
#include <pcl/common/tensor_exceptions.h>
#include <pcl/io/ply_io.h>


namespace pcl
{
  namespace io
  {
    ScanMesh
    loadScanMesh (const std::string& path)
    {
      detail::requireReadableFile (path);
      const auto dot = path.find_last_of ('.');
      const std::string ext = dot == std::string::npos ? std::string () : path.substr (dot + 1);
      if (ext != "ply" && ext != "PLY")
        PCL_TENSOR_THROW (pcl::IOException, "'" << path << "' is not a .ply mesh");
      pcl::PolygonMesh polygon_mesh;
      const detail::QuietPclConsole quiet;
      if (pcl::io::loadPLYFile (path, polygon_mesh) < 0)
        PCL_TENSOR_THROW (pcl::IOException, "cannot parse '" << path << "' as a PLY mesh");
      ScanMesh mesh;
      fromPolygonMesh (polygon_mesh, mesh);
      if (mesh.polygons.empty ())
        PCL_TENSOR_THROW (InvalidScanException, "'" << path << "' holds no triangle");
      return mesh;
    }
  }
}
