#pragma once
// The one solver switch: every solver membra has, its scene name and what it needs, in one
// table, and one call that solves with any of them. The scene reader, the runner, the memory
// estimate, the design, the viewer and `membra bench` all go through it, so a new solver is added
// here and nowhere else (docs/architecture.md, "Adding a solver").
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "membra/model/model.hpp"
#include "membra/solve/solve_report.hpp"

namespace membra {

struct NewtonCache;  // newton_workspace.hpp

enum class Solver {
  static_fire,       // "static": FIRE on stiffness-scaled masses (static_solver.hpp)
  dr_unit,           // "dr_unit": the same with one mass for all (plain dynamic relaxation)
  newton,            // "newton": shifted Newton with sparse Cholesky (newton_solver.hpp)
  ptc,               // "ptc": pseudo-transient continuation on the same Hessians
  rk4,               // "rk4": the paper's Runge-Kutta 4 time stepping (dynamics.hpp)
  symplectic_euler,  // "symplectic_euler": semi-implicit Euler time stepping
};

struct SolverInfo {
  Solver id;
  std::string_view name;      // as written in scenes and on the command line
  bool equilibrium;           // finds a static equilibrium (else steps in time with T)
  bool in_scenes;             // offered by simulation.solver (else `membra bench` only)
  double bytes_per_particle;  // memory a run needs with it (measured; docs/errors.md)
  std::string_view summary;   // one line for help texts
};

// The table, in the order help texts list it.
const std::vector<SolverInfo>& solver_table();
const SolverInfo& solver_info(Solver solver);
std::string_view solver_name(Solver solver);
// The solver called `name` (scene and bench names), or nothing.
std::optional<Solver> solver_from_name(std::string_view name);
// Names of the solvers a scene may choose (in_scenes), or of all of them.
// Newton and ptc: factorize Hessians, follow paths with a predictor and adaptive increments.
bool second_order(Solver solver);
std::vector<std::string_view> solver_names(bool scenes_only = true);

// Everything any solver reads; each takes what applies to it.
struct SolverSettings {
  double tolerance = 1e-6;          // converged when max |static force| <= tolerance x force_scale
  double force_scale = 1.0;         // N, normally k_stretch x grid spacing
  long max_iterations = 500000;     // static and dr_unit: iterations
  long newton_iterations = 500;     // newton: iterations
  double dt = 1e-4;                 // time stepping: T, s
  long steps = 10000;               // time stepping: steps at most
  bool stop_when_converged = true;  // time stepping
  double settle_after = 0.0;        // time stepping: no stop at rest before this time, s
  double max_seconds = 0.0;         // wall-time budget (0: none)
  std::function<void(const Progress&)> progress;
  std::function<void(const State&, long step)> on_check;  // time stepping: e.g. frames
  bool tangent_correction = true;             // newton: NewtonOptions::tangent_correction
  std::shared_ptr<NewtonCache> newton_cache;  // newton: setup kept between solves (may be null)
};

// Solves with `solver` from `state` (equilibrium solvers: to a nearby equilibrium; time
// stepping: for `steps` steps or until converged). Never throws on failure: the report says.
SolveReport solve_with(Solver solver, const Model& model, State& state,
                       const SolverSettings& settings);

}  // namespace membra
