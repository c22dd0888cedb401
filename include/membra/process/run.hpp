#pragma once
// Running a scene: prepare its membrane, carry out the protocol step by step (each step's path
// followed to equilibrium), summarise the end state.
#include <functional>
#include <memory>
#include <vector>

#include "membra/core/progress.hpp"
#include "membra/process/cut_after_motion.hpp"
#include "membra/process/path.hpp"
#include "membra/process/prepare.hpp"
#include "membra/process/run_result.hpp"
#include "membra/process/scene.hpp"

namespace membra {

// A run in progress, one step at a time: what run_scene does in one go, for front ends that let
// the user carry out the process step by step (the Python module's Membrane). The scene must
// outlive the run.
class SceneRun {
 public:
  // Prepares the scene's membrane (throws InputError as prepare_scene does).
  explicit SceneRun(const Scene& scene, ProgressFn progress = {});
  SceneRun(const SceneRun&) = delete;  // the frame recorder points into the result
  SceneRun& operator=(const SceneRun&) = delete;
  // Carries out one step and follows its path to equilibrium — or, given a `start` form (one
  // position per particle), applies the step's change in full and solves once from that form
  // (multilevel.hpp). Returns false when the solve diverged (the run is then over: further steps
  // are refused with std::logic_error).
  bool apply(const ProtocolStep& step, const Points* start = nullptr);
  // A solve of the scene as it stands (a scene without protocol: its only step).
  bool solve();
  // The run so far, summarised (a copy: steps may follow).
  RunResult result() const;
  // The run summarised and handed over; the run is empty afterwards.
  RunResult finish();
  const RunResult& partial() const { return r_; }
  bool diverged() const { return r_.solve.diverged; }

 private:
  bool record(StepReport step);
  void start_budget();
  // A cut after the sheet moved (cut_after_motion.hpp): pulled back, the sheet meshed again with
  // it and the run so far carried over; returns the cut as pulled back. The scene the run follows
  // is from then on its own copy, whose protocol is the steps applied, this cut and the scene's
  // steps after it.
  ProtocolStep remesh_for(const ProtocolStep& given);
  // The caller's progress with run_done filled in: the steps recorded so far and the current
  // one's step_done, each step weighted by its increments (1 without a path).
  ProgressFn whole_run(ProgressFn progress) const;
  const Scene* scene_;                // the scene as given, or own_scene_
  std::unique_ptr<Scene> own_scene_;  // with the cuts pulled back so far
  ProgressFn progress_;
  std::vector<ProtocolStep> applied_steps_;  // as applied (a cut after motion pulled back)
  std::vector<SheetForm> forms_;  // the continuum's form at the start of each applied step
  bool moved_ = false;            // a step has moved the sheet off its frame
  RunResult r_;
  FrameRecorder recorder_;
  std::function<double(const Vec2&)> curvature_field_;  // of the last curvature_map step
};

// The advice a run of `scene` that ended in `r` carries (RunResult::warnings): a grid too coarse
// for its pattern (grid_resolution.hpp), a form that passes through itself
// (self_intersection.hpp). run_scene fills it in; a run taken step by step asks for it.
std::vector<std::string> run_warnings(const Scene& scene, const RunResult& r);

// Runs a scene to the end. `progress` (optional) is called every so often. Throws InputError
// when a step cannot be carried out (a pattern that covers no spring).
RunResult run_scene(const Scene& scene, const ProgressFn& progress = {});

}  // namespace membra
