// The Python module's native part, `membra._membra`: thin bindings of the library (docs/python.md).
// The public API, with its docstrings, is the pure-Python package around it (python/membra/).
#include <pybind11/pybind11.h>

#include "bindings.hpp"

PYBIND11_MODULE(_membra, m) {
  m.doc() = "membra's native core; use the `membra` package, not this module";
  membra::python::bind_errors(m);
  membra::python::bind_scene(m);
  membra::python::bind_run(m);
  membra::python::bind_design(m);
}
