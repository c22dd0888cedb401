#include "membra/process/path.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "membra/core/stop_request.hpp"
#include "membra/measure/stress.hpp"
#include "membra/process/increment_walk.hpp"
#include "membra/solve/newton_solver.hpp"
#include "membra/solve/solver.hpp"

namespace membra {

void FrameRecorder::record(const Model& m, const Points& x, double thickness) {
  if (!frames || static_cast<int>(frames->size()) >= wanted) return;
  frames->push_back({x, vertex_stress(m, x, thickness)});
}

namespace {

// Applies `path` linearly over `seconds` of simulated time from now: set(t) at every check (a
// check every 50 steps: hundreds of small increments), the run kept going until the ramp is done.
void ramp_path(const Path& path, double seconds, const State& s, SolverSettings& o) {
  const double start = s.time;
  path.set(std::min(1.0, o.dt / seconds));
  o.settle_after = start + seconds;
  o.on_check = [&path, start, seconds, frames = std::move(o.on_check)](const State& st, long step) {
    path.set(std::min(1.0, (st.time - start) / seconds));
    if (frames) frames(st, step);
  };
}

}  // namespace

SolveReport solve_scene_step(const Scene& scene, const PreparedScene& p, State& s,
                             const std::string& stage, const ProgressFn& progress,
                             FrameRecorder* recorder, double tolerance, const Path* ramp,
                             std::shared_ptr<NewtonCache> newton_cache) {
  const SimulationSpec& sim = scene.simulation;
  const Model& m = p.membrane.sheet.model;
  SolverSettings o;
  // Time stepping runs once per step, always to the scene's tolerance.
  o.tolerance = tolerance < 0.0 || !sim.is_static() ? sim.tolerance : tolerance;
  o.force_scale = p.force_scale;
  o.max_iterations = sim.max_iterations;
  // Newton: at most 500 iterations a solve, fewer if the scene caps its solvers lower.
  o.newton_iterations = std::min<long>(o.newton_iterations, sim.max_iterations);
  o.dt = sim.dt;
  o.steps = sim.steps;
  o.stop_when_converged = sim.stop_when_converged;
  o.newton_cache = std::move(newton_cache);
  o.tangent_correction = sim.tangent_correction;
  if (p.deadline) {  // what is left of the run's budget; a spent budget stops the solve soon
    const double left =
        std::chrono::duration<double>(*p.deadline - std::chrono::steady_clock::now()).count();
    o.max_seconds = std::max(left, 1e-9);
  }
  // Every solve reports progress, so that a requested stop (core/stop_request.hpp) is seen.
  o.progress = [&](const Progress& pr) {
    Progress q = pr;
    q.stage = stage;
    throw_if_stop_requested(q);
    if (progress) progress(q);
  };
  if (!sim.is_static() && recorder && recorder->wanted > 0) {
    // Evenly over the run, at the first check past each frame time.
    const long every = std::max<long>(1, o.steps / recorder->wanted);
    const double t = p.membrane.sheet.material.thickness;
    o.on_check = [&m, recorder, every, t, next = every](const State& st, long step) mutable {
      if (step < next) return;
      recorder->record(m, st.x, t);
      next += every * ((step - next) / every + 1);
    };
  }
  if (ramp && !sim.is_static() && sim.ramp_seconds > 0.0) ramp_path(*ramp, sim.ramp_seconds, s, o);
  SolveReport r = solve_with(sim.solver, m, s, o);
  r.out_of_time =
      p.deadline && !r.converged && !r.diverged && std::chrono::steady_clock::now() >= *p.deadline;
  return r;
}

namespace {

// Adds a solve's work (iterations, passes, factorizations, time) to a total, not its outcome.
void add_work(SolveReport& total, const SolveReport& r) {
  total.iterations += r.iterations;
  total.force_passes += r.force_passes;
  total.factorizations += r.factorizations;
  total.setups += r.setups;
  total.negative_curvature_steps += r.negative_curvature_steps;
  total.lanczos_steps += r.lanczos_steps;
  total.tangent_corrections += r.tangent_corrections;
  total.increments += r.increments;
  total.increments_halved += r.increments_halved;
  total.wall_seconds += r.wall_seconds;
}

}  // namespace

void accumulate(SolveReport& total, const SolveReport& r) {
  add_work(total, r);
  total.saddle = r.saddle;
  total.out_of_time = total.out_of_time || r.out_of_time;
  total.residual = r.residual;
  total.residual_relative = r.residual_relative;
  total.converged = r.converged;
  total.diverged = r.diverged;
  total.message = r.message;
}

namespace {

// Follows a gradual path with an equilibrium solver, increment by increment (IncrementWalk:
// halving, growth and the secant predictor with Newton).
void follow_increments(const Scene& scene, const PreparedScene& p, State& s,
                       const std::string& name, const Path& path, const ProgressFn& progress,
                       FrameRecorder& recorder, SolveReport& total) {
  const double thickness = p.membrane.sheet.material.thickness;
  const bool newton = second_order(scene.simulation.solver);
  IncrementWalk walk(path, scene.simulation, newton);
  // Every increment solves the same sheet: Newton keeps its pattern and analysis from one to the
  // next (at 128^2 about a factorization's cost; docs/solver.md), and frees them
  // with the path.
  const auto cache = newton ? make_newton_cache() : nullptr;
  // Each solve's progress says how much of the path was done before it.
  const ProgressFn along = [&](const Progress& pr) {
    if (!progress) return;
    Progress q = pr;
    q.step_done = walk.done_fraction();
    progress(q);
  };
  while (!walk.done() && !total.diverged) {
    const double tolerance = walk.begin(s.x, &p.membrane.sheet.model);
    const SolveReport r =
        solve_scene_step(scene, p, s, walk.stage(name), along, nullptr, tolerance, nullptr, cache);
    if (r.out_of_time) {  // the run's budget is spent: stop here, not halve or go on
      accumulate(total, r);
      recorder.record(p.membrane.sheet.model, s.x, thickness);  // the state it stopped in
      break;
    }
    if (!r.converged && !r.diverged && walk.halve(s.x)) {
      add_work(total, r);  // its work counts; its end state does not
      ++total.increments_halved;
      continue;
    }
    accumulate(total, r);
    ++total.increments;
    recorder.record(p.membrane.sheet.model, s.x, thickness);
    walk.accept(s.x, r.iterations);
  }
}

}  // namespace

StepReport follow_path(const Scene& scene, const PreparedScene& p, State& s,
                       const std::string& name, const Path& path, const ProgressFn& progress,
                       FrameRecorder& recorder) {
  StepReport rep{name, {}, 0};
  if (path.kind == Path::Kind::none) return rep;
  if (path.kind == Path::Kind::at_once) {
    rep.solve = solve_scene_step(scene, p, s, name, progress);
    return rep;
  }
  if (!scene.simulation.is_static()) {
    // Time stepping lets go at once, as the paper's tool does, or over simulation.ramp_seconds.
    if (scene.simulation.ramp_seconds > 0.0) {
      rep.solve = solve_scene_step(scene, p, s, name, progress, &recorder, -1.0, &path);
      return rep;
    }
    path.set(1.0);
    rep.solve = solve_scene_step(scene, p, s, name, progress, &recorder);
    return rep;
  }
  follow_increments(scene, p, s, name, path, progress, recorder, rep.solve);
  return rep;
}

}  // namespace membra
