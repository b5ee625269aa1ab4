/*
 * pcl_tensor Python module: scans from NumPy arrays or files, and their sensors.
 */
#pragma once

#include <pcl/common/scan_viewpoint.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

namespace pcl_tensor_python
{
  /** \brief One scan as the bindings take it: its points, its sensor, and where it came from. */
  struct ScanInput
  {
    pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
    pcl::ScanViewpoint viewpoint = pcl::ScanViewpoint::fromPositiveZ ();
    std::string name;       ///< the file's path, or "array"
    double load_ms = 0.0;   ///< reading the file (0 for an array)
  };

  /** \brief A cloud from an N x 3 (unorganized) or H x W x 3 (organized, NaN in empty cells) float array.
    * \throw pybind11::value_error for another shape or dtype, an empty array or fewer than three finite points
    */
  pcl::PointCloud<pcl::PointXYZ>::Ptr
  cloudFromArray (const pybind11::handle& points, const std::string& what);

  /** \brief The finite points of \a cloud as a float64 N x 3 array. */
  pybind11::array_t<double>
  finitePoints (const pcl::PointCloud<pcl::PointXYZ>& cloud);

  /** \brief A scan from a path (str or os.PathLike; read as pcl_tensor_register reads it, with the GIL
    * released) or from an array; \a viewpoint None keeps the file's sensor (+z for an array), a
    * Viewpoint replaces it, and three numbers put a perspective sensor there looking at the scan.
    */
  ScanInput
  scanInput (const pybind11::handle& scan, const pybind11::handle& viewpoint, const std::string& what);

  /** \brief Bind Viewpoint (pcl::ScanViewpoint). */
  void
  bindViewpoint (pybind11::module_& m);
}
