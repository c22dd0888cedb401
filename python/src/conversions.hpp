#pragma once
// Library values as Python objects: a run's end state as numpy arrays in the outputs' units
// (mm, 1/m^2, MPa), JSON documents as dicts.
#include <pybind11/numpy.h>
#include <nlohmann/json.hpp>

#include "membra/process/run_result.hpp"

namespace membra::python {

namespace py = pybind11;

py::array_t<double> positions_mm(const Points& x);                   // n x 3
py::array_t<double> paper_positions_mm(const Sheet& sheet);          // n x 2
py::array_t<int> triangles(const Sheet& sheet);                      // m x 3
py::array_t<double> per_particle(const std::vector<double>& values,  // n, times `scale`
                                 double scale);
py::object json_to_python(const nlohmann::json& j);  // through Python's json module

}  // namespace membra::python
