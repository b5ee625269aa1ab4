/*
 * pcl_tensor: automatic pairwise registration of range images with tensors.
 */
#include <pcl/io/range_grid_ply.h>
#include <pcl/common/point_tests.h>
#include <pcl/common/tensor_exceptions.h>
#include <pcl/conversions.h>
#include <pcl/io/ply_io.h>

#include <limits>

namespace pcl
{
  namespace io
  {
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
      pcl::PCLPointCloud2 blob;
      pcl::toPCLPointCloud2 (cloud, blob);
      // max_digits10 of float: the text gives back exactly the same floats.
      pcl::PLYWriter writer;
      if (writer.writeASCII (path, blob, Eigen::Vector4f::Zero (), Eigen::Quaternionf::Identity (),
                             std::numeric_limits<float>::max_digits10, false) < 0)
        PCL_TENSOR_THROW (pcl::IOException, "cannot write '" << path << "'");
    }
  }
}
