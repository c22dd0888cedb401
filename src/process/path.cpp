#include "membra/process/path.hpp"

#include <algorithm>

#include "membra/measure/stress.hpp"
#include "membra/solve/solver.hpp"

namespace membra {

void FrameRecorder::record(const Model& m, const Points& x, double thickness) {
  if (!frames || static_cast<int>(frames->size()) >= wanted) return;
  frames->push_back({x, vertex_stress(m, spring_stress(m, x, thickness))});
}

SolveReport solve_scene_step(const Scene& scene, const PreparedScene& p, State& s,
                             const std::string& stage, const ProgressFn& progress,
                             FrameRecorder* recorder, double tolerance) {
  const SimulationSpec& sim = scene.simulation;
  const Model& m = p.membrane.sheet.model;
  SolverSettings o;
  // Time stepping runs once per step, always to the scene's tolerance.
  o.tolerance = tolerance < 0.0 || !sim.is_static() ? sim.tolerance : tolerance;
  o.force_scale = p.force_scale;
  o.max_iterations = sim.max_iterations;
  o.dt = sim.dt;
  o.steps = sim.steps;
  o.stop_when_converged = sim.stop_when_converged;
  if (progress)
    o.progress = [&](const Progress& pr) {
      Progress q = pr;
      q.stage = stage;
      progress(q);
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
  return solve_with(sim.solver, m, s, o);
}

void accumulate(SolveReport& total, const SolveReport& r) {
  total.iterations += r.iterations;
  total.force_passes += r.force_passes;
  total.factorizations += r.factorizations;
  total.negative_curvature_steps += r.negative_curvature_steps;
  total.saddle = r.saddle;
  total.wall_seconds += r.wall_seconds;
  total.residual = r.residual;
  total.residual_relative = r.residual_relative;
  total.converged = r.converged;
  total.diverged = r.diverged;
  total.message = r.message;
}

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
    // Time stepping lets go at once, as the paper's tool does.
    path.set(1.0);
    rep.solve = solve_scene_step(scene, p, s, name, progress, &recorder);
    return rep;
  }
  const double thickness = p.membrane.sheet.material.thickness;
  const int n = path.increments;
  // Newton starts each increment from the secant predictor: the last increment's motion
  // repeated, so that it begins near the next equilibrium instead of at the last one.
  const bool predict = scene.simulation.solver == Solver::newton;
  Points before, last;  // the equilibria of the two increments before this one
  for (int k = 1; k <= n && !rep.solve.diverged; ++k) {
    path.set(static_cast<double>(k) / n);
    if (predict && before.cols() == s.x.cols()) s.x += last - before;
    const std::string stage = name + " " + std::to_string(k) + "/" + std::to_string(n);
    // Intermediate increments only carry the sheet along the path: a looser tolerance there
    // (simulation.path_tolerance) saves their slow tails; the last one is solved in full.
    const double tolerance = k < n ? scene.simulation.path_tolerance : scene.simulation.tolerance;
    accumulate(rep.solve, solve_scene_step(scene, p, s, stage, progress, nullptr, tolerance));
    recorder.record(p.membrane.sheet.model, s.x, thickness);
    if (predict) before = std::move(last), last = s.x;
  }
  return rep;
}

}  // namespace membra
