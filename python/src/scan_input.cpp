/*
 * pcl_tensor Python module: scans from NumPy arrays or files, and their sensors.
 */
#include "scan_input.h"

#include <pcl/common/time.h>
#include <pcl/io/range_scan_io.h>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>

namespace py = pybind11;

namespace pcl_tensor_python
{
  namespace
  {
    bool
    isPath (const py::handle& obj)
    {
      return py::isinstance<py::str> (obj) || py::hasattr (obj, "__fspath__");
    }

    std::string
    modelName (pcl::ScanViewpoint::Model model)
    {
      switch (model)
      {
        case pcl::ScanViewpoint::Model::perspective: return "perspective";
        case pcl::ScanViewpoint::Model::orthographic: return "orthographic";
        case pcl::ScanViewpoint::Model::pushbroom: return "pushbroom";
      }
      return "unknown";
    }

    pcl::ScanViewpoint::Model
    modelFromName (const std::string& name)
    {
      if (name == "perspective")
        return pcl::ScanViewpoint::Model::perspective;
      if (name == "orthographic")
        return pcl::ScanViewpoint::Model::orthographic;
      if (name == "pushbroom")
        return pcl::ScanViewpoint::Model::pushbroom;
      throw py::value_error ("a viewpoint's model is 'perspective', 'orthographic' or 'pushbroom', not '" + name + "'");
    }

    /** A rigid 4 x 4 pose: orthonormal rotation with determinant 1 and last row 0 0 0 1. */
    Eigen::Affine3d
    rigidPose (const Eigen::Matrix4d& m)
    {
      const Eigen::Matrix3d r = m.topLeftCorner<3, 3> ();
      const bool rigid = m.allFinite () && m.row (3).isApprox (Eigen::RowVector4d (0, 0, 0, 1)) &&
                         (r.transpose () * r).isApprox (Eigen::Matrix3d::Identity (), 1e-6) && r.determinant () > 0.0;
      if (!rigid)
        throw py::value_error ("sensor_pose must be a rigid 4x4 transform (rotation and translation)");
      return Eigen::Affine3d (m);
    }

    Eigen::Vector3d
    vector3 (const py::handle& obj, const std::string& what)
    {
      const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure (obj);
      if (!a || a.size () != 3 || a.ndim () != 1)
        throw py::value_error (what + " must be three numbers");
      const Eigen::Vector3d v (a.at (0), a.at (1), a.at (2));
      if (!v.allFinite ())
        throw py::value_error (what + " must be finite");
      return v;
    }
  }

  pcl::PointCloud<pcl::PointXYZ>::Ptr
  cloudFromArray (const py::handle& points, const std::string& what)
  {
    const py::array raw = py::array::ensure (points);
    if (!raw)
      throw py::value_error (what + " must be a path or an N x 3 array of points");
    if (raw.dtype ().kind () != 'f')
      throw py::value_error (what + " must hold floating-point coordinates (float32 or float64), got dtype " +
                             std::string (py::str (raw.dtype ())));
    const bool organized = raw.ndim () == 3;
    if (!((raw.ndim () == 2 || organized) && raw.shape (raw.ndim () - 1) == 3))
      throw py::value_error (what + " must have shape (N, 3), or (H, W, 3) for an organized scan, got " +
                             std::string (py::str (py::tuple (py::cast (std::vector<py::ssize_t> (raw.shape (), raw.shape () + raw.ndim ()))))));
    if (raw.size () == 0)
      throw py::value_error (what + " is empty");
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure (raw);
    pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
    const std::size_t n = static_cast<std::size_t> (a.size () / 3);
    cloud->resize (n);
    const double* data = a.data ();
    std::size_t finite = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
      auto& p = (*cloud)[i];
      p.x = static_cast<float> (data[3 * i]);
      p.y = static_cast<float> (data[3 * i + 1]);
      p.z = static_cast<float> (data[3 * i + 2]);
      finite += std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z);
    }
    if (organized)
    {
      cloud->width = static_cast<std::uint32_t> (raw.shape (1));
      cloud->height = static_cast<std::uint32_t> (raw.shape (0));
    }
    cloud->is_dense = finite == n;
    if (finite < 3)
      throw py::value_error (what + " has " + std::to_string (finite) + " finite points; a scan needs at least three");
    return cloud;
  }

  py::array_t<double>
  finitePoints (const pcl::PointCloud<pcl::PointXYZ>& cloud)
  {
    std::vector<double> xyz;
    xyz.reserve (3 * cloud.size ());
    for (const auto& p : cloud)
      if (std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z))
        xyz.insert (xyz.end (), {double (p.x), double (p.y), double (p.z)});
    py::array_t<double> out ({static_cast<py::ssize_t> (xyz.size () / 3), py::ssize_t (3)});
    std::copy (xyz.begin (), xyz.end (), out.mutable_data ());
    return out;
  }

  ScanInput
  scanInput (const py::handle& scan, const py::handle& viewpoint, const std::string& what)
  {
    ScanInput in;
    if (isPath (scan))
    {
      in.name = py::str (py::module_::import ("os").attr ("fspath") (scan));
      pcl::io::RangeScan loaded;
      {
        py::gil_scoped_release release;
        pcl::StopWatch watch;
        loaded = pcl::io::loadRangeScan (in.name);
        in.load_ms = watch.getTime ();
      }
      in.cloud = loaded.cloud;
      in.viewpoint = loaded.viewpoint;
    }
    else
    {
      in.name = "array";
      in.cloud = cloudFromArray (scan, what);
    }
    if (viewpoint.is_none ())
      return in;
    if (py::isinstance<pcl::ScanViewpoint> (viewpoint))
      in.viewpoint = viewpoint.cast<pcl::ScanViewpoint> ();
    else
      in.viewpoint = pcl::ScanViewpoint::lookingAtScan (vector3 (viewpoint, what + "'s viewpoint"), *in.cloud);
    return in;
  }

  void
  bindViewpoint (py::module_& m)
  {
    using V = pcl::ScanViewpoint;
    py::class_<V> (m, "Viewpoint",
                   "Where a scan was seen from (C++ pcl::ScanViewpoint): a perspective sensor at a point, an "
                   "orthographic one along a direction, or a pushbroom (line-scan) sensor. The sensor looks along "
                   "its own +z axis; sensor_pose is the sensor frame in the scan's frame.")
      .def (py::init ([] (const Eigen::Matrix4d& pose, const std::string& model) {
              V v;
              v.sensor_pose = rigidPose (pose);
              v.model = modelFromName (model);
              return v;
            }),
            py::arg ("sensor_pose"), py::arg ("model") = "perspective")
      .def_static ("positive_z", &V::fromPositiveZ, "An orthographic sensor on the +z side, looking down -z (the default).")
      .def_static ("looking_at", [] (const Eigen::Vector3d& position, const Eigen::Vector3d& target) {
                     return V::lookingAt (position, target); },
                   py::arg ("position"), py::arg ("target"), "A perspective sensor at position looking at target.")
      .def_static ("pushbroom", [] (const Eigen::Vector3d& point, const Eigen::Vector3d& direction, const Eigen::Vector3d& target) {
                     return V::pushbroom (point, direction, target); },
                   py::arg ("axis_point"), py::arg ("axis_direction"), py::arg ("target"),
                   "A pushbroom sensor whose lines of sight fan out from a line, looking toward target.")
      .def_property_readonly ("model", [] (const V& v) { return modelName (v.model); })
      .def_property_readonly ("sensor_pose", [] (const V& v) { return Eigen::Matrix4d (v.sensor_pose.matrix ()); })
      .def ("__repr__", [] (const V& v) {
        const Eigen::Vector3d t = v.sensor_pose.translation ();
        return "Viewpoint(model='" + modelName (v.model) + "', position=(" + std::to_string (t.x ()) + ", " +
               std::to_string (t.y ()) + ", " + std::to_string (t.z ()) + "))";
      });
  }
}
