#include "membra/solve/dynamics.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "membra/model/forces.hpp"
#include "membra/solve/integrator.hpp"

namespace membra {
SolveReport run_dynamics(const Model& model, State& state, const DynamicsOptions& o) {
  auto integrator = make_integrator(o.method);
  if (!integrator) throw std::invalid_argument("unknown integrator '" + o.method + "'");
  if (!(o.dt > 0.0) || !std::isfinite(o.dt)) throw std::invalid_argument("time step must be > 0");
  if (o.steps < 0) throw std::invalid_argument("number of steps must be >= 0");
  if (!(o.force_scale > 0.0)) throw std::invalid_argument("force scale must be > 0");
  const int check_every = std::max(1, o.check_every);

  const Stopwatch clock;
  auto seconds = [&] { return clock.seconds(); };
  // Explicit instability grows positions exponentially; a sheet 100x its initial size, or any
  // NaN, is a blow-up, never a form.
  const double size0 = std::max(sheet_extent(state.x), 1e-12);

  SolveReport r;
  int small_in_a_row = 0;
  for (long step = 1; step <= o.steps; ++step) {
    integrator->step(model, state, o.dt);
    ++r.iterations;
    r.force_passes += integrator->force_passes_per_step();
    if (step % check_every != 0 && step != o.steps) continue;

    if (!state.x.allFinite() || !state.v.allFinite() || sheet_extent(state.x) > 100.0 * size0) {
      r.diverged = true;
      std::ostringstream msg;
      msg << o.method << " diverged at step " << step << " (t = " << state.time
          << " s): " << (state.x.allFinite() ? "the sheet blew up" : "positions became NaN/Inf")
          << ". Try a smaller time step T (now " << o.dt << " s), more damping D, or the static "
          << "solver.";
      r.message = msg.str();
      r.wall_seconds = seconds();
      return r;
    }
    // A ramp moves the model in on_check: measure the residual of the model the next steps see,
    // and count quiet checks only once the ramp is over, so no ramp part is left unsimulated.
    if (o.on_check) o.on_check(state, step);
    r.residual = max_residual_force(model, state.x);
    r.residual_relative = r.residual / o.force_scale;
    const bool quiet = r.residual_relative <= o.tolerance && state.time >= o.settle_after;
    small_in_a_row = quiet ? small_in_a_row + 1 : 0;
    if (o.progress) o.progress({"", step, o.steps, r.residual_relative, seconds(), -1.0, -1.0});
    if (o.stop_when_converged && small_in_a_row >= o.confirm_checks) break;
    if (o.max_seconds > 0.0 && seconds() > o.max_seconds) break;
  }
  if (r.iterations == 0) {
    r.residual = max_residual_force(model, state.x);
    r.residual_relative = r.residual / o.force_scale;
  }
  r.converged = r.residual_relative <= o.tolerance;
  r.wall_seconds = seconds();
  r.message = summary_message(o.method, r, o.tolerance, "steps");
  return r;
}

}  // namespace membra
