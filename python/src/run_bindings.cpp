// Runs: the one-shot run of a scene and the step-by-step run, and what they return.
#include <memory>
#include <mutex>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <nlohmann/json.hpp>

#include "bindings.hpp"
#include "conversions.hpp"
#include "membra/measure/stress.hpp"
#include "membra/output/report.hpp"
#include "membra/process/run.hpp"
#include "membra/render/run_outputs.hpp"
#include "progress_bridge.hpp"

namespace membra::python {

namespace {

// A finished run with the scene it ran.
struct NativeResult {
  ScenePtr scene;
  RunResult run;
};

// Writes every file `membra run` writes; returns the render note ("" or why no PNG).
std::string write_result(const NativeResult& r, const std::filesystem::path& dir,
                         const std::vector<double>& curvature_range,
                         const std::vector<double>& stress_range) {
  const PictureOptions opts{curvature_range, stress_range};
  py::gil_scoped_release nogil;
  OutputSet out(dir);
  const StagedRun staged = stage_run_outputs(*r.scene, r.run, opts, out);
  out.commit();
  return staged.render_note;
}

void bind_result(py::module_& m) {
  py::class_<NativeResult, std::shared_ptr<NativeResult>>(m, "NativeResult")
      .def_property_readonly(
          "positions",
          [](const NativeResult& r) { return positions_mm(r.run.prepared.membrane.state.x); })
      .def_property_readonly(
          "paper_positions",
          [](const NativeResult& r) { return paper_positions_mm(r.run.prepared.membrane.sheet); })
      .def_property_readonly(
          "triangles",
          [](const NativeResult& r) { return triangles(r.run.prepared.membrane.sheet); })
      .def_property_readonly(
          "gaussian_curvature",
          [](const NativeResult& r) { return per_particle(r.run.curvature.density, 1.0); })
      .def_property_readonly(
          "stress", [](const NativeResult& r) { return per_particle(r.run.vertex_stress, 1e-6); })
      .def_property_readonly(
          "report",
          [](const NativeResult& r) { return json_to_python(make_report(*r.scene, r.run)); })
      .def_property_readonly("diverged", [](const NativeResult& r) { return r.run.solve.diverged; })
      .def_property_readonly("warnings", [](const NativeResult& r) { return r.run.warnings; })
      .def("write", &write_result, py::arg("dir"), py::arg("curvature_range"),
           py::arg("stress_range"));
}

std::shared_ptr<NativeResult> run(const ScenePtr& scene, const py::object& progress) {
  const ProgressFn fn = progress_bridge(progress);
  auto r = std::make_shared<NativeResult>();
  r->scene = scene;
  py::gil_scoped_release nogil;
  r->run = run_scene(*scene, fn);
  return r;
}

// A run carried out one step at a time (membra.Membrane). Each step arrives as the last step of
// a scene parsed with it, which the run keeps alive with the steps it applied.
class NativeRun {
 public:
  NativeRun(ScenePtr scene, py::object progress)
      : scene_(std::move(scene)), progress_(std::move(progress)) {
    py::gil_scoped_release nogil;
    run_ = std::make_unique<SceneRun>(*scene_, progress_bridge(progress_));
  }
  bool apply_last(const ScenePtr& with_step) {
    if (with_step->protocol.empty()) throw std::invalid_argument("the scene has no step");
    kept_.push_back(with_step);
    return guarded([&] { return run_->apply(with_step->protocol.back()); });
  }
  bool solve() {
    return guarded([&] { return run_->solve(); });
  }
  std::shared_ptr<NativeResult> result() {
    auto r = std::make_shared<NativeResult>();
    // The scene with the steps applied so far: its pattern is the one the outputs draw.
    r->scene = kept_.empty() ? scene_ : kept_.back();
    py::gil_scoped_release nogil;
    const std::lock_guard lock(mutex_);
    r->run = run_->result();
    r->run.warnings = run_warnings(*r->scene, r->run);
    return r;
  }
  py::array_t<double> positions() {
    Points x;
    {
      py::gil_scoped_release nogil;  // a step may be running in another thread: wait for it
      const std::lock_guard lock(mutex_);
      x = run_->partial().prepared.membrane.state.x;
    }
    return positions_mm(x);
  }

 private:
  // Runs a step or solve without the GIL and one at a time. A step cut short (Ctrl-C, an error
  // in the progress callback) leaves the membrane half-changed: the run refuses further steps.
  template <class F>
  bool guarded(F&& f) {
    if (broken_)
      throw std::runtime_error(
          "a step of this membrane was interrupted half-way; start a new Membrane");
    py::gil_scoped_release nogil;
    const std::lock_guard lock(mutex_);
    try {
      return f();
    } catch (...) {
      broken_ = true;
      throw;
    }
  }

  ScenePtr scene_;
  py::object progress_;
  std::vector<ScenePtr> kept_;
  std::unique_ptr<SceneRun> run_;
  std::mutex mutex_;
  bool broken_ = false;
};

}  // namespace

void bind_run(py::module_& m) {
  bind_result(m);
  m.def("run", &run, py::arg("scene"), py::arg("progress"));
  py::class_<NativeRun>(m, "NativeRun")
      .def(py::init<ScenePtr, py::object>(), py::arg("scene"), py::arg("progress"))
      .def("apply_last", &NativeRun::apply_last, py::arg("scene"))
      .def("solve", &NativeRun::solve)
      .def("result", &NativeRun::result)
      .def_property_readonly("positions", &NativeRun::positions);
}

}  // namespace membra::python
