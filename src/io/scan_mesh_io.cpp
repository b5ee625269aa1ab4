/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/scan_mesh_io.h>
#include "file_input.h"
#include <pcl/common/tensor_exceptions.h>
#include <pcl/io/ply_io.h>
#include <pcl/io/atomic_file.h>
#include "byte_codec.h"

#include <sstream>


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

    namespace
    {
      /** The header of saveScanMesh's files: the vertex fields of toPolygonMesh(), then the triangles. */
      std::string
      plyHeader (const ScanMesh& mesh)
      {
        std::ostringstream h;
        h << "ply\nformat binary_little_endian 1.0\ncomment written by pcl_tensor\n"
          << "element vertex " << mesh.cloud->size () << "\n";
        for (const char* field : {"x", "y", "z", "normal_x", "normal_y", "normal_z", "curvature"})
          h << "property float " << field << "\n";
        h << "element face " << mesh.polygons.size () << "\nproperty list uchar int vertex_indices\nend_header\n";
        return h.str ();
      }
    }

    void
    saveScanMesh (const std::string& path, const ScanMesh& mesh)
    {
      constexpr std::size_t vertex_bytes = 7 * sizeof (float), triangle_bytes = 1 + 3 * sizeof (std::int32_t);
      detail::ByteWriter out;
      out.bytes () = plyHeader (mesh);
      out.bytes ().reserve (out.bytes ().size () + mesh.cloud->size () * vertex_bytes + mesh.polygons.size () * triangle_bytes);
      for (const auto& p : *mesh.cloud)
        out.put (p.x).put (p.y).put (p.z).put (p.normal_x).put (p.normal_y).put (p.normal_z).put (p.curvature);
      for (const auto& poly : mesh.polygons)
      {
        if (poly.vertices.size () > 255)  // the PLY list's count is a uchar
          PCL_TENSOR_THROW (pcl::IOException, "cannot write '" << path << "': a polygon of " << poly.vertices.size () << " vertices");
        out.put (static_cast<std::uint8_t> (poly.vertices.size ()));
        for (const auto idx : poly.vertices)
          out.put (static_cast<std::int32_t> (idx));
      }
      writeFileAtomically (path, out.bytes ());
    }
  }
}
