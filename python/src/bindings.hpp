#pragma once
// The parts of the native module, one file each.
#include <memory>

#include <pybind11/pybind11.h>

#include "membra/process/scene.hpp"

namespace membra::python {

namespace py = pybind11;

// membra.SceneError (with .pointer and .detail) for InputError, membra.OutputError for
// OutputError.
void bind_errors(py::module_& m);
// Scene: parse / load / override / validate.
void bind_scene(py::module_& m);
// Run results, the one-shot run and the step-by-step run.
void bind_run(py::module_& m);
// Inverse design.
void bind_design(py::module_& m);

// A typed scene shared between Python objects (a run keeps its scene alive); never changed after
// it was read (pybind11's holders cannot be pointers to const).
using ScenePtr = std::shared_ptr<Scene>;

}  // namespace membra::python
