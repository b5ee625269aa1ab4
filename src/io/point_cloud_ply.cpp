/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/point_cloud_ply.h>
#include <pcl/io/atomic_file.h>
#include "byte_codec.h"

#include <sstream>

namespace pcl
{
  namespace io
  {
    void
    savePointCloudPLY (const std::string& path, const pcl::PointCloud<pcl::PointXYZ>& cloud)
    {
      const bool organized = cloud.height > 1;
      std::ostringstream header;
      header << "ply\nformat binary_little_endian 1.0\ncomment written by pcl_tensor\n"
             << "element vertex " << cloud.size () << "\nproperty float x\nproperty float y\nproperty float z\n";
      if (organized)
        header << "element camera 1\nproperty int viewportx\nproperty int viewporty\n";
      header << "end_header\n";
      detail::ByteWriter out;
      out.bytes () = header.str ();
      out.bytes ().reserve (out.bytes ().size () + cloud.size () * 3 * sizeof (float) + 2 * sizeof (std::int32_t));
      for (const auto& p : cloud)
        out.put (p.x).put (p.y).put (p.z);
      if (organized)
        out.put (static_cast<std::int32_t> (cloud.width)).put (static_cast<std::int32_t> (cloud.height));
      writeFileAtomically (path, out.bytes ());
    }
  }
}
