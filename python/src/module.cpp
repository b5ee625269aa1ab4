/*
 * pcl_tensor Python module: automatic registration of range images with tensors (Mian, Bennamoun &
 * Owens, IJCV 2006) from NumPy and Open3D. A thin shell over the C++ library: every call runs the
 * library's own code with the GIL released.
 */
#include "params.h"
#include "scan_input.h"

#include <pcl/common/tensor_exceptions.h>
#include <pcl/exceptions.h>
#include <pcl/io/registration_report_json.h>
#include <pcl/registration/multiview_tensor_registration.h>
#include <pcl/registration/tensor_registration.h>
#include <pcl/surface/scan_volumetric_integration.h>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

namespace py = pybind11;
using namespace pcl_tensor_python;

namespace
{
  /** What register() returns. */
  struct RegistrationResult
  {
    bool registered = false;
    bool ambiguous = false;
    Eigen::Matrix4d transform = Eigen::Matrix4d::Identity ();
    py::object rival_transform = py::none ();
    py::dict report;
  };

  /** What build_model() returns. */
  struct ModelResult
  {
    py::array_t<double> vertices, normals;
    py::array_t<std::int64_t> faces;
    std::vector<py::object> poses;
    std::vector<std::string> status;
    std::vector<std::string> names;
    py::dict report;
  };

  py::dict
  toDict (const pcl::io::JsonReport& report)
  {
    return py::module_::import ("json").attr ("loads") (pcl::io::dumpJson (report));
  }

  /** The threads keyword: a non-negative count, 0 (the default) for every core. */
  unsigned
  threadsOf (const py::object& threads)
  {
    if (threads.is_none ())
      return 0;
    const long n = threads.cast<long> ();
    if (n < 0)
      throw py::value_error ("threads must be 0 (every core) or positive");
    return static_cast<unsigned> (n);
  }

  /** Pops \a name from \a kwargs (None when absent). */
  py::object
  pop (py::dict& kwargs, const char* name)
  {
    if (!kwargs.contains (name))
      return py::none ();
    py::object value = kwargs[name];
    PyDict_DelItemString (kwargs.ptr (), name);
    return value;
  }

  RegistrationResult
  registerScans (const py::object& model, const py::object& scene, const py::object& model_viewpoint,
                 const py::object& scene_viewpoint, py::kwargs kwargs)
  {
    const py::object dims = pop (kwargs, "object_dimensions");
    const unsigned threads = threadsOf (pop (kwargs, "threads"));
    pcl::registration::TensorRegistrationParams params;
    applyKeywords (py::cast (&params, py::return_value_policy::reference), kwargs, "register");
    pcl::registration::TensorRegistration registration;
    registration.setParams (params);
    registration.setNumberOfThreads (threads);
    if (!dims.is_none ())
    {
      pcl::ObjectDimensions d;
      d.D = dims.cast<Eigen::Vector3d> ();
      if (!d.D.allFinite () || !(d.D.array () > 0.0).all ())
        throw py::value_error ("object_dimensions must be three positive numbers");
      registration.setObjectDimensions (d);
    }
    const ScanInput m = scanInput (model, model_viewpoint, "model");
    const ScanInput s = scanInput (scene, scene_viewpoint, "scene");
    registration.setInputTarget (m.cloud);
    registration.setInputSource (s.cloud);
    registration.setTargetViewpoint (m.viewpoint);
    registration.setSourceViewpoint (s.viewpoint);
    {
      py::gil_scoped_release release;
      pcl::PointCloud<pcl::PointXYZ> aligned;
      registration.alignOrThrow (aligned);
    }
    const auto& r = registration.getReport ();
    RegistrationResult out;
    out.registered = r.registered;
    out.ambiguous = r.ambiguous;
    out.transform = r.transform.cast<double> ();
    if (r.ambiguous)
      out.rival_transform = py::cast (Eigen::Matrix4d (r.rival_transform.cast<double> ()));
    pcl::io::JsonReport report = pcl::io::toJson (r);
    report["timings_ms"]["load"] = m.load_ms + s.load_ms;
    out.report = toDict (report);
    return out;
  }

  std::vector<ScanInput>
  modelInputs (const py::sequence& views, const py::object& viewpoints)
  {
    if (!viewpoints.is_none () && py::len (viewpoints) != py::len (views))
      throw py::value_error ("viewpoints must give one entry (or None) per view");
    std::vector<ScanInput> inputs;
    for (std::size_t i = 0; i < py::len (views); ++i)
    {
      const std::string what = "view " + std::to_string (i);
      const py::object viewpoint = viewpoints.is_none () ? py::object (py::none ()) : py::object (viewpoints[py::int_ (i)]);
      inputs.push_back (scanInput (views[py::int_ (i)], viewpoint, what));
      if (inputs.back ().name == "array")
        inputs.back ().name = what;
    }
    return inputs;
  }

  void
  fillMesh (const pcl::ScanMesh& mesh, ModelResult& out)
  {
    const auto n = static_cast<py::ssize_t> (mesh.cloud->size ());
    out.vertices = py::array_t<double> ({n, py::ssize_t (3)});
    out.normals = py::array_t<double> ({n, py::ssize_t (3)});
    auto v = out.vertices.mutable_unchecked<2> ();
    auto nn = out.normals.mutable_unchecked<2> ();
    for (py::ssize_t i = 0; i < n; ++i)
    {
      const auto& p = (*mesh.cloud)[static_cast<std::size_t> (i)];
      v (i, 0) = p.x, v (i, 1) = p.y, v (i, 2) = p.z;
      nn (i, 0) = p.normal_x, nn (i, 1) = p.normal_y, nn (i, 2) = p.normal_z;
    }
    out.faces = py::array_t<std::int64_t> ({static_cast<py::ssize_t> (mesh.polygons.size ()), py::ssize_t (3)});
    auto f = out.faces.mutable_unchecked<2> ();
    for (std::size_t i = 0; i < mesh.polygons.size (); ++i)
      for (int k = 0; k < 3; ++k)
        f (static_cast<py::ssize_t> (i), k) = mesh.polygons[i].vertices[static_cast<std::size_t> (k)];
  }

  ModelResult
  buildModel (const py::sequence& views, bool loop, const py::object& viewpoints, const py::object& pairs,
              const py::object& known_poses, py::kwargs kwargs)
  {
    if (py::isinstance<py::str> (views) || py::len (views) < 2)
      throw py::value_error ("build_model needs a sequence of at least two views");
    const py::object integration_kwargs = pop (kwargs, "integration");
    const unsigned threads = threadsOf (pop (kwargs, "threads"));
    pcl::registration::MultiviewRegistrationParams params;
    params.loop = loop;
    applyKeywords (py::cast (&params, py::return_value_policy::reference), kwargs, "build_model");
    pcl::VolumetricIntegrationParams integration_params;
    if (!integration_kwargs.is_none ())
      applyKeywords (py::cast (&integration_params, py::return_value_policy::reference),
                     integration_kwargs.cast<py::dict> (), "build_model.integration");
    // Parameters are checked before any view is read.
    pcl::registration::MultiviewTensorRegistration registration;
    registration.setParams (params);
    registration.setNumberOfThreads (threads);
    pcl::ScanVolumetricIntegration integration;
    integration.setParams (integration_params);
    integration.setNumberOfThreads (threads);
    if (!pairs.is_none ())
      registration.setPairs (pairs.cast<pcl::registration::ViewPairs> ());

    if (!known_poses.is_none () && py::len (known_poses) != py::len (views))
      throw py::value_error ("known_poses must give one entry (a 4 x 4 pose or None) per view");
    std::vector<pcl::registration::MultiviewInput> inputs;
    for (const auto& in : modelInputs (views, viewpoints))
    {
      inputs.push_back ({in.name, in.cloud, in.viewpoint, nullptr});
      const py::object pose = known_poses.is_none () ? py::object (py::none ()) : py::object (known_poses[py::int_ (inputs.size () - 1)]);
      if (!pose.is_none ())
      {
        inputs.back ().pose_known = true;
        inputs.back ().known_pose.matrix () = pose.cast<Eigen::Matrix4d> ();
      }
    }
    pcl::registration::MultiviewRegistrationResult result;
    pcl::ScanMesh mesh;
    {
      py::gil_scoped_release release;
      result = registration.compute (inputs);
      integration.setInputViews (pcl::registration::registeredIntegrationViews (result));
      integration.reconstruct (mesh);
    }
    ModelResult out;
    fillMesh (mesh, out);
    for (const auto& v : result.views)
    {
      out.names.push_back (v.name);
      out.status.push_back (v.registered ? "registered" : "not_registered");
      out.poses.push_back (v.registered ? py::cast (Eigen::Matrix4d (v.pose.matrix ())) : py::none ());
    }
    pcl::io::JsonReport report = pcl::io::toJson (result);
    report["volume"] = pcl::io::toJson (integration.getReport ());
    report["mesh"] = {{"vertices", mesh.cloud->size ()}, {"triangles", mesh.polygons.size ()}};
    out.report = toDict (report);
    return out;
  }

  /** PCL's and the library's exceptions as the Python ones a user expects. */
  void
  translateExceptions ()
  {
    py::register_exception_translator ([] (std::exception_ptr p) {
      try
      {
        if (p)
          std::rethrow_exception (p);
      }
      catch (const pcl::IOException& e) { PyErr_SetString (PyExc_OSError, e.what ()); }
      catch (const pcl::BadArgumentException& e) { PyErr_SetString (PyExc_ValueError, e.what ()); }
      catch (const pcl::InvalidScanException& e) { PyErr_SetString (PyExc_ValueError, e.what ()); }
      catch (const pcl::MemoryLimitException& e) { PyErr_SetString (PyExc_MemoryError, e.what ()); }
      catch (const pcl::PCLException& e) { PyErr_SetString (PyExc_RuntimeError, e.what ()); }
    });
  }

  void
  bindResults (py::module_& m)
  {
    py::class_<RegistrationResult> (m, "RegistrationResult", "What register() found.")
      .def_readonly ("registered", &RegistrationResult::registered, "True only when one pose passed verification.")
      .def_readonly ("ambiguous", &RegistrationResult::ambiguous, "Two distinct poses passed: not registered.")
      .def_readonly ("transform", &RegistrationResult::transform, "4x4: scene points into the model's frame (identity when not registered).")
      .def_readonly ("rival_transform", &RegistrationResult::rival_transform, "The second pose when ambiguous, else None.")
      .def_readonly ("report", &RegistrationResult::report, "The fields of pcl_tensor_register --json.")
      .def ("__bool__", [] (const RegistrationResult& r) { return r.registered; })
      .def ("__repr__", [] (const RegistrationResult& r) {
        return std::string ("RegistrationResult(registered=") + (r.registered ? "True" : "False") +
               ", ambiguous=" + (r.ambiguous ? "True" : "False") + ")";
      });
    py::class_<ModelResult> (m, "ModelResult", "What build_model() made.")
      .def_readonly ("vertices", &ModelResult::vertices, "V x 3 model vertices, in the first registered view's frame.")
      .def_readonly ("normals", &ModelResult::normals, "V x 3 unit vertex normals.")
      .def_readonly ("faces", &ModelResult::faces, "F x 3 triangles, indices into vertices.")
      .def_readonly ("poses", &ModelResult::poses, "One 4x4 pose per view (view -> model frame), None when not registered.")
      .def_readonly ("status", &ModelResult::status, "'registered' or 'not_registered', per view.")
      .def_readonly ("names", &ModelResult::names, "Each view's file, or 'view I' for an array.")
      .def_readonly ("report", &ModelResult::report, "The fields of pcl_tensor_model --json.")
      .def ("__repr__", [] (const ModelResult& r) {
        return "ModelResult(vertices=" + std::to_string (r.vertices.shape (0)) + ", faces=" +
               std::to_string (r.faces.shape (0)) + ", registered=" +
               std::to_string (std::count (r.status.begin (), r.status.end (), "registered")) + "/" +
               std::to_string (r.status.size ()) + ")";
      });
  }
}

PYBIND11_MODULE (pcl_tensor, m)
{
  m.doc () = "Automatic registration of range images with third-order tensors (Mian, Bennamoun & Owens, "
             "IJCV 2006): pairwise registration that reports 'not registered' rather than a wrong pose, "
             "and whole models from many views.";
  translateExceptions ();
  bindParams (m);
  bindViewpoint (m);
  bindResults (m);

  m.def ("load_scan", [] (const py::object& path) {
           const ScanInput in = scanInput (path, py::none (), "path");
           return py::make_tuple (finitePoints (*in.cloud), in.viewpoint);
         },
         py::arg ("path"),
         "Read a range scan (PLY with or without range_grid, or PCD) as pcl_tensor_register reads it.\n"
         "Returns (points, viewpoint): the finite points as a float64 N x 3 array, and the sensor.\n"
         "Raises OSError when the file cannot be read, ValueError when it holds under three points.");
  m.def ("register", &registerScans, py::arg ("model"), py::arg ("scene"), py::arg ("model_viewpoint") = py::none (),
         py::arg ("scene_viewpoint") = py::none (),
         "Register scene to model automatically. model and scene are paths or N x 3 (or H x W x 3) float\n"
         "arrays; a viewpoint is a Viewpoint, three numbers (a perspective sensor there) or None (the file's\n"
         "sensor, or +z for an array). Keyword parameters are RegistrationParams' fields, with the same names\n"
         "and defaults (a dict sets a nested struct: preparation=dict(target_faces=800)), plus\n"
         "object_dimensions=(X, Y, Z) and threads (0, the default: every core). Returns a RegistrationResult; registered is False when no pose could be\n"
         "verified, or two distinct poses could (ambiguous).");
  m.def ("build_model", &buildModel, py::arg ("views"), py::arg ("loop") = false, py::arg ("viewpoints") = py::none (),
         py::arg ("pairs") = py::none (), py::arg ("known_poses") = py::none (),
         "Register views (paths or arrays, each overlapping one before it, or with pairs=[(i, j), ...]) and\n"
         "integrate them into one mesh, as pcl_tensor_model does. loop=True closes a turntable's loop.\n"
         "known_poses: one 4 x 4 pose (view -> common frame) or None per view; the views with a pose keep\n"
         "it, and only the others are registered to them (pcl_tensor_model --keep-poses).\n"
         "Keyword parameters are ModelParams' fields (pairwise=dict(...) for the pairwise ones), plus\n"
         "integration=dict(...) for IntegrationParams, and threads (0, the default: every core). Returns a\n"
         "ModelResult.");
  m.attr ("__version__") = PCL_TENSOR_VERSION;
}
