/*
 * pcl_tensor Python module: the parameter structs, bound field by field with the C++ names and defaults.
 */
#include "params.h"

#include <pcl/registration/multiview_tensor_registration.h>
#include <pcl/surface/scan_volumetric_integration.h>

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace pcl_tensor_python
{
  namespace
  {
    /** "Name(field=value, ...)" from the bound fields, so a params object prints what it holds. */
    std::string
    reprOf (const py::handle& self)
    {
      std::string out = py::str (py::type::of (self).attr ("__name__"));
      out += "(";
      bool first = true;
      for (const auto& field : py::type::of (self).attr ("_fields"))
      {
        const std::string name = py::str (field);
        out += (first ? "" : ", ") + name + "=" + std::string (py::repr (self.attr (name.c_str ())));
        first = false;
      }
      return out + ")";
    }

    /** A struct bound with its field list (for repr and keyword checks) and value semantics. */
    template <typename T> py::class_<T>
    bindStruct (py::module_& m, const char* name, const char* doc, const std::vector<const char*>& fields)
    {
      py::class_<T> c (m, name, doc);
      c.def (py::init<> ());
      py::list names;
      for (const char* f : fields)
        names.append (f);
      c.attr ("_fields") = py::tuple (names);
      c.def ("__repr__", [] (const py::object& self) { return reprOf (self); });
      c.def ("__copy__", [] (const T& self) { return T (self); });
      c.def ("__deepcopy__", [] (const T& self, const py::dict&) { return T (self); });
      return c;
    }

    void
    bindEnums (py::module_& m)
    {
      py::enum_<pcl::registration::TensorMatchOrder> (m, "MatchOrder", "The order in which tensor matches are verified.")
        .value ("SCENE_ORDER", pcl::registration::TensorMatchOrder::SCENE_ORDER)
        .value ("BEST_FIRST", pcl::registration::TensorMatchOrder::BEST_FIRST);
      py::enum_<pcl::ScanMeshNormalEstimation::Method> (m, "NormalMethod", "How the normals of M'_i are computed (Section 2).")
        .value ("FACE_AVERAGE", pcl::ScanMeshNormalEstimation::Method::FACE_AVERAGE)
        .value ("FINE_NEIGHBOURHOOD", pcl::ScanMeshNormalEstimation::Method::FINE_NEIGHBOURHOOD);
    }

    void
    bindPairwise (py::module_& m)
    {
      using P = pcl::ScanPreparationParams;
      bindStruct<P> (m, "PreparationParams", "Range image -> M_i -> M'_i (Section 2); C++ pcl::ScanPreparationParams.",
                     {"edge_std_devs", "target_faces", "normal_method", "normal_radius_resolutions", "stray_fragment_gap",
                      "stray_fragment_fraction", "speck_max_pixels", "speck_jump", "reduction_grid_step"})
        .def_readwrite ("edge_std_devs", &P::edge_std_devs)
        .def_readwrite ("target_faces", &P::target_faces)
        .def_readwrite ("normal_method", &P::normal_method)
        .def_readwrite ("normal_radius_resolutions", &P::normal_radius_resolutions)
        .def_readwrite ("stray_fragment_gap", &P::stray_fragment_gap)
        .def_readwrite ("stray_fragment_fraction", &P::stray_fragment_fraction)
        .def_readwrite ("speck_max_pixels", &P::speck_max_pixels)
        .def_readwrite ("speck_jump", &P::speck_jump)
        .def_readwrite ("reduction_grid_step", &P::reduction_grid_step);

      using V = pcl::registration::TensorVerificationParams;
      bindStruct<V> (m, "VerificationParams", "Local verification (Section 4.1); C++ pcl::registration::TensorVerificationParams.",
                     {"coarse_dimension_fraction", "correspondence_fraction", "coarse_distance", "count_both_views",
                      "fine_distance", "fine_dimension_tolerance", "fine_dimension_fraction", "checked_dimensions",
                      "icp_iterations", "icp_max_distance", "icp_final_distance", "icp_coarse_stage_step",
                      "icp_max_normal_angle", "sample_points", "free_space_distance", "free_space_fraction", "empty_space_margin"})
        .def_readwrite ("coarse_dimension_fraction", &V::coarse_dimension_fraction)
        .def_readwrite ("correspondence_fraction", &V::correspondence_fraction)
        .def_readwrite ("coarse_distance", &V::coarse_distance)
        .def_readwrite ("count_both_views", &V::count_both_views)
        .def_readwrite ("fine_distance", &V::fine_distance)
        .def_readwrite ("fine_dimension_tolerance", &V::fine_dimension_tolerance)
        .def_readwrite ("fine_dimension_fraction", &V::fine_dimension_fraction)
        .def_readwrite ("checked_dimensions", &V::checked_dimensions)
        .def_readwrite ("icp_iterations", &V::icp_iterations)
        .def_readwrite ("icp_max_distance", &V::icp_max_distance)
        .def_readwrite ("icp_final_distance", &V::icp_final_distance)
        .def_readwrite ("icp_coarse_stage_step", &V::icp_coarse_stage_step)
        .def_readwrite ("icp_max_normal_angle", &V::icp_max_normal_angle)
        .def_readwrite ("sample_points", &V::sample_points)
        .def_readwrite ("free_space_distance", &V::free_space_distance)
        .def_readwrite ("free_space_fraction", &V::free_space_fraction)
        .def_readwrite ("empty_space_margin", &V::empty_space_margin);

      using R = pcl::registration::TensorRegistrationParams;
      bindStruct<R> (m, "RegistrationParams", "Every parameter of pairwise registration; C++ pcl::registration::TensorRegistrationParams.",
                     {"preparation", "grid_size", "partners_per_vertex", "min_normal_angle", "region_growing",
                      "overlap_threshold", "correlation_threshold", "fallback_overlap_threshold",
                      "fallback_correlation_threshold", "theta_bin_width", "order", "scene_tensor_batches",
                      "batch_hypotheses", "verification", "max_hypotheses", "repeat_rotation", "repeat_translation",
                      "ambiguity_checks", "ambiguity_rotation", "probe_rivals", "rival_margin", "rival_empty_space_margin",
                      "rival_empty_space_fraction", "rival_dimension_factor", "rival_icp_max_normal_angle"})
        .def_readwrite ("preparation", &R::preparation)
        .def_readwrite ("grid_size", &R::grid_size)
        .def_readwrite ("partners_per_vertex", &R::partners_per_vertex)
        .def_readwrite ("min_normal_angle", &R::min_normal_angle)
        .def_readwrite ("region_growing", &R::region_growing)
        .def_readwrite ("overlap_threshold", &R::overlap_threshold)
        .def_readwrite ("correlation_threshold", &R::correlation_threshold)
        .def_readwrite ("fallback_overlap_threshold", &R::fallback_overlap_threshold)
        .def_readwrite ("fallback_correlation_threshold", &R::fallback_correlation_threshold)
        .def_readwrite ("theta_bin_width", &R::theta_bin_width)
        .def_readwrite ("order", &R::order)
        .def_readwrite ("scene_tensor_batches", &R::scene_tensor_batches)
        .def_readwrite ("batch_hypotheses", &R::batch_hypotheses)
        .def_readwrite ("verification", &R::verification)
        .def_readwrite ("max_hypotheses", &R::max_hypotheses)
        .def_readwrite ("repeat_rotation", &R::repeat_rotation)
        .def_readwrite ("repeat_translation", &R::repeat_translation)
        .def_readwrite ("ambiguity_checks", &R::ambiguity_checks)
        .def_readwrite ("ambiguity_rotation", &R::ambiguity_rotation)
        .def_readwrite ("probe_rivals", &R::probe_rivals)
        .def_readwrite ("rival_margin", &R::rival_margin)
        .def_readwrite ("rival_empty_space_margin", &R::rival_empty_space_margin)
        .def_readwrite ("rival_empty_space_fraction", &R::rival_empty_space_fraction)
        .def_readwrite ("rival_dimension_factor", &R::rival_dimension_factor)
        .def_readwrite ("rival_icp_max_normal_angle", &R::rival_icp_max_normal_angle);
    }

    void
    bindMultiview (py::module_& m)
    {
      using G = pcl::registration::GlobalVerificationParams;
      bindStruct<G> (m, "GlobalVerificationParams", "Global verification (Section 4.2).", {"tolerance", "checked_dimensions"})
        .def_readwrite ("tolerance", &G::tolerance)
        .def_readwrite ("checked_dimensions", &G::checked_dimensions);

      using I = pcl::registration::MultiviewIcpParams;
      bindStruct<I> (m, "GlobalStepParams", "The global step: simultaneous point-to-plane ICP (Section 5).",
                     {"max_iterations", "max_distance", "sample_points", "max_normal_angle", "skip_boundary",
                      "min_rotation", "min_translation"})
        .def_readwrite ("max_iterations", &I::max_iterations)
        .def_readwrite ("max_distance", &I::max_distance)
        .def_readwrite ("sample_points", &I::sample_points)
        .def_readwrite ("max_normal_angle", &I::max_normal_angle)
        .def_readwrite ("skip_boundary", &I::skip_boundary)
        .def_readwrite ("min_rotation", &I::min_rotation)
        .def_readwrite ("min_translation", &I::min_translation);

      using M = pcl::registration::MultiviewRegistrationParams;
      // The C++ field `global` is a Python keyword: it is `global_` here.
      bindStruct<M> (m, "ModelParams", "Every parameter of multiview registration; C++ pcl::registration::MultiviewRegistrationParams.",
                     {"pairwise", "global_verification", "object_dimensions", "loop", "max_references", "keep_best",
                      "global_registration", "global_", "min_overlap"})
        .def_readwrite ("pairwise", &M::pairwise)
        .def_readwrite ("global_verification", &M::global_verification)
        .def_readwrite ("object_dimensions", &M::object_dimensions)
        .def_readwrite ("loop", &M::loop)
        .def_readwrite ("max_references", &M::max_references)
        .def_readwrite ("keep_best", &M::keep_best)
        .def_readwrite ("global_registration", &M::global_registration)
        .def_readwrite ("global_", &M::global)
        .def_readwrite ("min_overlap", &M::min_overlap);

      using T = pcl::VolumetricIntegrationParams;
      bindStruct<T> (m, "IntegrationParams", "Volumetric integration and marching cubes; C++ pcl::VolumetricIntegrationParams.",
                     {"voxel_size", "voxel_size_resolutions", "truncation_voxels", "border_ramp_edges",
                      "pixels_per_resolution", "max_memory_bytes", "min_component_fraction"})
        .def_readwrite ("voxel_size", &T::voxel_size)
        .def_readwrite ("voxel_size_resolutions", &T::voxel_size_resolutions)
        .def_readwrite ("truncation_voxels", &T::truncation_voxels)
        .def_readwrite ("border_ramp_edges", &T::border_ramp_edges)
        .def_readwrite ("pixels_per_resolution", &T::pixels_per_resolution)
        .def_readwrite ("max_memory_bytes", &T::max_memory_bytes)
        .def_readwrite ("min_component_fraction", &T::min_component_fraction);
    }

    bool
    isBoundStruct (const py::handle& value)
    {
      return py::hasattr (py::type::of (value), "_fields");
    }
  }

  void
  bindParams (py::module_& m)
  {
    bindEnums (m);
    bindPairwise (m);
    bindMultiview (m);
  }

  void
  applyKeywords (py::handle target, const py::dict& kwargs, const std::string& where)
  {
    const py::tuple fields = py::type::of (target).attr ("_fields");
    for (const auto& item : kwargs)
    {
      const std::string name = py::str (item.first);
      if (!fields.contains (py::str (name)))
        throw py::type_error (where + " has no parameter '" + name + "'; its parameters are " +
                              py::repr (fields).cast<std::string> ());
      const py::object current = target.attr (name.c_str ());
      if (isBoundStruct (current) && py::isinstance<py::dict> (item.second))
      {
        // The field is a struct held by value: set its fields on a copy and store the copy back.
        py::object copy = current.attr ("__copy__") ();
        applyKeywords (copy, item.second.cast<py::dict> (), where + "." + name);
        target.attr (name.c_str ()) = copy;
        continue;
      }
      try
      {
        target.attr (name.c_str ()) = item.second;
      }
      catch (py::error_already_set& e)
      {
        if (!e.matches (PyExc_TypeError))
          throw;
        throw py::type_error (where + "." + name + ": " + std::string (py::str (e.value ())));
      }
    }
  }
}
