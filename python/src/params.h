/*
 * pcl_tensor Python module: the parameter structs, bound field by field with the C++ names and defaults.
 */
#pragma once

#include <pybind11/pybind11.h>

namespace pcl_tensor_python
{
  /** \brief Bind RegistrationParams, PreparationParams, VerificationParams, ModelParams and the
    * structs they hold, and the enums of their fields. */
  void
  bindParams (pybind11::module_& m);

  /** \brief Set the fields of the bound struct \a target from \a kwargs, by name. A dict given for a
    * field that is itself a struct sets that struct's fields.
    * \throw pybind11::type_error for a name that is not a field, or a value of the wrong type
    */
  void
  applyKeywords (pybind11::handle target, const pybind11::dict& kwargs, const std::string& where);
}
