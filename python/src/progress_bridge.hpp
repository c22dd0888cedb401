#pragma once
// Progress of a solve running without the GIL, passed to a Python callable (or None), and the
// way a Ctrl-C in Python stops a long solve: the interrupt is checked at every progress report.
#include <functional>

#include <pybind11/pybind11.h>

#include "membra/core/progress.hpp"

namespace membra::python {

namespace py = pybind11;

// A library callback for `Event`s that checks for Ctrl-C and passes each event, made a dict by
// `to_dict`, to `callback` (a Python callable, or None). `callback` must outlive every call of
// the returned function (the callers hold it).
template <class Event, class ToDict>
std::function<void(const Event&)> python_callback(const py::object& callback, ToDict to_dict) {
  PyObject* cb = callback.ptr();  // borrowed: copies of the function must not touch refcounts
  return [cb, to_dict](const Event& e) {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (cb != Py_None) py::reinterpret_borrow<py::object>(cb)(to_dict(e));
  };
}

inline py::dict progress_dict(const Progress& p) {
  py::dict d;
  d["stage"] = p.stage;
  d["iteration"] = p.iteration;
  d["max_iterations"] = p.max_iterations;
  d["residual_relative"] = p.residual_relative;
  d["wall_seconds"] = p.wall_seconds;
  d["step_done"] = p.step_done;  // share of the step's path done, -1: not a path
  d["run_done"] = p.run_done;    // share of the whole run done, -1: unknown
  return d;
}

inline ProgressFn progress_bridge(const py::object& callback) {
  return python_callback<Progress>(callback, progress_dict);
}

}  // namespace membra::python
