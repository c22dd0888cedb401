#pragma once
// Paths: how the sheet is carried from its state before a step to the state after it. A step
// that changes the sheet gradually (release, grow, add_springs, curvature_map) gives a path of
// increments and a set(t) that moves its change to t in (0, 1]; an equilibrium solver follows it
// quasi-statically, increment by increment, so the sheet picks the branch a slow process would.
// The CLI's runner follows a path to the end at once; the viewer drives the same path in time
// slices.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "membra/process/prepare.hpp"
#include "membra/process/run_result.hpp"
#include "membra/process/scene.hpp"

namespace membra {

struct NewtonCache;  // solve/newton_workspace.hpp

struct Path {
  enum class Kind {
    none,     // nothing to solve (impregnate: the resin cures in place)
    at_once,  // the step changed the sheet at once: one solve to equilibrium
    gradual,  // increments of set(t), a solve after each
  } kind = Kind::none;
  int increments = 1;
  std::function<void(double)> set;  // gradual: the step's change at t (called with k/increments)
};

// Records frames: the state and the stress of its springs at that moment, until `wanted` are
// recorded.
struct FrameRecorder {
  int wanted = 0;
  std::vector<Frame>* frames = nullptr;
  void record(const Model& m, const Points& x, double thickness);
};

// Solves for equilibrium (or steps in time) with the scene's solver. `tolerance` < 0: the
// scene's. Frames are recorded during time stepping when `recorder` is given. `ramp` (time
// stepping with simulation.ramp_seconds > 0): the path whose change is applied over that time,
// set at every check, the run not ending at rest before the ramp does. `newton_cache`: Newton's
// setup kept from the last solve of this sheet (solve/newton_workspace.hpp).
SolveReport solve_scene_step(const Scene& scene, const PreparedScene& p, State& s,
                             const std::string& stage, const ProgressFn& progress,
                             FrameRecorder* recorder = nullptr, double tolerance = -1.0,
                             const Path* ramp = nullptr,
                             std::shared_ptr<NewtonCache> newton_cache = nullptr);

// Follows `path` to its end: with an equilibrium solver, set(k / n) and a solve for k = 1..n
// (a frame recorded after each); with time stepping, set(1) and one run of dynamics (frames along
// it), or set(t) ramped over simulation.ramp_seconds during that run. The returned report is named
// `name`; its solve sums the path's solves.
StepReport follow_path(const Scene& scene, const PreparedScene& p, State& s,
                       const std::string& name, const Path& path, const ProgressFn& progress,
                       FrameRecorder& recorder);

// Adds a solve's counts to a total; residual and convergence are the latest.
void accumulate(SolveReport& total, const SolveReport& r);

}  // namespace membra
