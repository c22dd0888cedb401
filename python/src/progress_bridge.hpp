#pragma once
// Progress of a solve running without the GIL, passed to a Python callable (or None), and the
// way a Ctrl-C in Python stops a long solve: the interrupt is checked at every progress report.
#include <pybind11/pybind11.h>

#include "membra/core/progress.hpp"

namespace membra::python {

namespace py = pybind11;

// `callback` must outlive every call of the returned function (the callers hold it).
inline ProgressFn progress_bridge(const py::object& callback) {
  PyObject* cb = callback.ptr();  // borrowed: copies of the function must not touch refcounts
  return [cb](const Progress& p) {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (cb == Py_None) return;
    py::dict d;
    d["stage"] = p.stage;
    d["iteration"] = p.iteration;
    d["max_iterations"] = p.max_iterations;
    d["residual_relative"] = p.residual_relative;
    d["wall_seconds"] = p.wall_seconds;
    py::reinterpret_borrow<py::object>(cb)(d);
  };
}

}  // namespace membra::python
