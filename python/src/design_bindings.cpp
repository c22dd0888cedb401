// Inverse design: a design file (or its JSON) in, the best stencil's form and report out.
#include <memory>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <nlohmann/json.hpp>

#include "bindings.hpp"
#include "conversions.hpp"
#include "membra/core/input_error.hpp"
#include "membra/design/inverse_design.hpp"
#include "membra/io/design_reader.hpp"
#include "membra/output/calibration_store.hpp"
#include "membra/output/design_files.hpp"
#include "membra/render/design_outputs.hpp"
#include "progress_bridge.hpp"

namespace membra::python {

namespace {

using DesignPtr = std::shared_ptr<DesignSpec>;  // never changed after it was read

// One forward simulation of the search, as a dict for the Python callback.
py::dict iteration_dict(const DesignIteration& it) {
  py::dict d;
  d["index"] = it.index;
  d["rms_error"] = it.rms_error;
  d["max_error"] = it.max_error;
  d["resin_share"] = it.resin_share;
  d["pieces"] = it.pieces;
  d["density_scale"] = it.scale;
  d["seconds"] = it.seconds;
  d["best"] = it.best;
  d["note"] = it.note;
  // "density" or "pieces" (adjoint iterates: rms to their target points) or "stencil"
  d["stage"] = it.stage;
  d["objective"] = it.objective;
  d["gradient_norm"] = it.gradient_norm;
  return d;
}

// `cache`: keep and reuse stencil calibrations in the default cache directory, as the CLI does.
std::shared_ptr<DesignResult> design(const DesignPtr& spec, const py::object& progress,
                                     bool cache) {
  const auto on_iteration = python_callback<DesignIteration>(progress, iteration_dict);
  auto r = std::make_shared<DesignResult>();
  DesignSpec run = *spec;
  if (const auto dir = default_cache_dir(); cache && !dir.empty())
    run.calibration_cache = calibration_store(dir);
  py::gil_scoped_release nogil;
  *r = run_design(run, on_iteration);
  return r;
}

std::string write_design(const DesignResult& r, const std::filesystem::path& dir) {
  py::gil_scoped_release nogil;
  OutputSet out(dir);
  const std::string note = stage_design_outputs(r, out);
  out.commit();
  return note;
}

void bind_design_result(py::module_& m) {
  py::class_<DesignResult, std::shared_ptr<DesignResult>>(m, "NativeDesignResult")
      .def_readonly("rms_error", &DesignResult::rms_error)
      .def_readonly("max_error", &DesignResult::max_error)
      .def_readonly("flat_error", &DesignResult::flat_error)
      .def_readonly("reachable", &DesignResult::reachable)
      .def_readonly("message", &DesignResult::message)
      .def_property_readonly(
          "positions",
          [](const DesignResult& r) { return positions_mm(r.run.prepared.membrane.state.x); })
      .def_property_readonly(
          "triangles",
          [](const DesignResult& r) { return triangles(r.run.prepared.membrane.sheet); })
      .def_property_readonly(
          "scene",
          [](const DesignResult& r) { return json_to_python(design_scene(r.spec, r.stencil)); })
      .def_property_readonly(
          "report", [](const DesignResult& r) { return json_to_python(make_design_report(r)); })
      .def("write", &write_design, py::arg("dir"));
}

}  // namespace

void bind_design(py::module_& m) {
  py::class_<DesignSpec, DesignPtr>(m, "NativeDesignSpec").def_readonly("name", &DesignSpec::name);
  m.def(
      "load_design",
      [](const std::filesystem::path& file) {
        return std::make_shared<DesignSpec>(load_design(file));
      },
      py::arg("file"));
  m.def(
      "parse_design",
      [](const std::string& text, const std::filesystem::path& base_dir) {
        nlohmann::json j;
        try {
          j = nlohmann::json::parse(text);
        } catch (const nlohmann::json::parse_error& e) {
          throw InputError("design", std::string("malformed JSON: ") + e.what());
        }
        return std::make_shared<DesignSpec>(parse_design(j, base_dir));
      },
      py::arg("text"), py::arg("base_dir"));
  bind_design_result(m);
  m.def("design", &design, py::arg("spec"), py::arg("progress"), py::arg("cache") = true);
}

}  // namespace membra::python
