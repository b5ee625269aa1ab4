/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/range_grid_ply.h>
#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>

#include <fstream>
#include <limits>
#include <sstream>

namespace pcl
{
  namespace io
  {
    namespace
    {
      /** The header of a raw Stanford scan: the grid size as obj_info, vertices, then the grid. */
      void
      writeHeader (std::ostream& out, const pcl::PointCloud<pcl::PointXYZ>& cloud, std::size_t finite)
      {
        out << "ply\nformat ascii 1.0\ncomment written by pcl_tensor (range image with range_grid)\n"
            << "obj_info num_cols " << cloud.width << "\nobj_info num_rows " << cloud.height << "\n"
            << "element vertex " << finite << "\nproperty float x\nproperty float y\nproperty float z\n"
            << "element range_grid " << cloud.size () << "\nproperty list uchar int vertex_indices\nend_header\n";
      }
    }

    void
    saveRangeGridPLY (const std::string& path, const pcl::PointCloud<pcl::PointXYZ>& cloud)
    {
      if (!cloud.isOrganized () || cloud.height < 2)
        PCL_TENSOR_THROW (pcl::BadArgumentException, "saveRangeGridPLY: '" << path
                          << "' needs an organized cloud, got " << cloud.width << "x" << cloud.height);
      std::size_t finite = 0;
      for (const auto& p : cloud)
        finite += pcl::isXYZFinite (p) ? 1 : 0;
      if (finite == 0)
        PCL_TENSOR_THROW (pcl::BadArgumentException, "saveRangeGridPLY: '" << path << "' would hold no finite point");
      std::ostringstream out;
      writeHeader (out, cloud, finite);
      // pcl::PLYWriter prints floats with 6 significant digits; max_digits10 (9) reads back exactly.
      out.precision (std::numeric_limits<float>::max_digits10);
      for (const auto& p : cloud)
        if (pcl::isXYZFinite (p))
          out << p.x << ' ' << p.y << ' ' << p.z << '\n';
      // Grid cells in row-major order: "1 k" names the k-th vertex, "0" an empty cell.
      std::size_t k = 0;
      for (const auto& p : cloud)
        if (pcl::isXYZFinite (p))
          out << "1 " << k++ << '\n';
        else
          out << "0\n";
      std::ofstream file (path);
      if (!(file << out.str ()) || !file.flush ())
        PCL_TENSOR_THROW (pcl::IOException, "cannot write '" << path << "'");
    }
  }
}
