// Library exceptions as Python exceptions. SceneError carries the JSON pointer of the field at
// fault, so that a notebook can point at it.
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "membra/core/input_error.hpp"
#include "membra/output/output_set.hpp"

namespace membra::python {

void bind_errors(py::module_& m) {
  static py::exception<InputError> scene_error(m, "SceneError", PyExc_ValueError);
  static py::exception<OutputError> output_error(m, "OutputError", PyExc_OSError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      py::object err = py::reinterpret_borrow<py::object>(scene_error.ptr())(e.what());
      err.attr("pointer") = e.where();
      err.attr("detail") = e.detail();
      PyErr_SetObject(scene_error.ptr(), err.ptr());
    } catch (const OutputError& e) {
      PyErr_SetString(output_error.ptr(), e.what());
    }
  });
}

}  // namespace membra::python
