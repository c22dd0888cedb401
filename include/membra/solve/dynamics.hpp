#pragma once
// Time stepping of a model with an explicit integrator, with convergence and divergence checks.
#include <functional>
#include <string>

#include "membra/model/model.hpp"
#include "membra/solve/solve_report.hpp"

namespace membra {

struct DynamicsOptions {
  std::string method = "rk4";  // integrator name, see make_integrator()
  double dt = 1e-4;            // T, time step, s
  long steps = 10000;          // maximum number of steps
  // Convergence: max |static force| <= tolerance x force_scale, held over `confirm_checks`
  // consecutive checks (a vibrating sheet passes through equilibrium at full speed, so one small
  // value proves nothing).
  double tolerance = 1e-6;
  double force_scale = 1.0;  // N, normally k_stretch x grid spacing
  bool stop_when_converged = true;
  double settle_after = 0.0;  // s of simulated time: at rest before it is not the end (a ramp)
  int check_every = 50;       // steps between residual and divergence checks
  int confirm_checks = 3;
  double max_seconds = 0.0;                               // wall-time budget (0: none)
  std::function<void(const Progress&)> progress;          // called at every check
  std::function<void(const State&, long step)> on_check;  // e.g. to record animation frames
};

// Runs up to `steps` steps from `state`. Never throws on divergence: the report says so and the
// state must not be used. Throws std::invalid_argument for an unknown method or bad options.
SolveReport run_dynamics(const Model& model, State& state, const DynamicsOptions& options);

}  // namespace membra
