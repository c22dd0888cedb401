#include "membra/solve/solver.hpp"

#include <stdexcept>

#include "membra/solve/dynamics.hpp"
#include "membra/solve/newton_solver.hpp"
#include "membra/solve/static_solver.hpp"

namespace membra {

const std::vector<SolverInfo>& solver_table() {
  // Memory per particle: measured 1.7 kB (static) and 12 kB (newton's Cholesky factor), with a
  // margin; newton's exact and projected Hessians with their element slots add about 10 kB
  // (estimated from the element counts; docs/errors.md).
  static const std::vector<SolverInfo> table = {
      {Solver::static_fire, "static", true, true, 2.5e3,
       "FIRE on stiffness-scaled masses (the viewer's live relaxation; fastest on spring nets)"},
      {Solver::newton, "newton", true, true, 28e3,
       "Newton on analytic Hessians with sparse Cholesky and saddle escapes (the default)"},
      {Solver::rk4, "rk4", false, true, 2.5e3, "the paper's Runge-Kutta 4, time step T"},
      {Solver::symplectic_euler, "symplectic_euler", false, true, 2.5e3,
       "semi-implicit Euler, time step T"},
      {Solver::dr_unit, "dr_unit", true, false, 2.5e3,
       "FIRE with one mass for all (plain dynamic relaxation, a benchmark baseline)"},
      {Solver::ptc, "ptc", true, false, 28e3,
       "pseudo-transient continuation on Newton's Hessians (a benchmark candidate, not kept)"},
  };
  return table;
}

const SolverInfo& solver_info(Solver solver) {
  for (const SolverInfo& s : solver_table())
    if (s.id == solver) return s;
  throw std::logic_error("solver missing from solver_table()");
}

std::string_view solver_name(Solver solver) {
  return solver_info(solver).name;
}

std::optional<Solver> solver_from_name(std::string_view name) {
  for (const SolverInfo& s : solver_table())
    if (s.name == name) return s.id;
  return std::nullopt;
}

bool second_order(Solver solver) {
  return solver == Solver::newton || solver == Solver::ptc;
}

std::vector<std::string_view> solver_names(bool scenes_only) {
  std::vector<std::string_view> names;
  for (const SolverInfo& s : solver_table())
    if (s.in_scenes || !scenes_only) names.push_back(s.name);
  return names;
}

SolveReport solve_with(Solver solver, const Model& model, State& state, const SolverSettings& in) {
  switch (solver) {
    case Solver::static_fire:
    case Solver::dr_unit: {
      StaticOptions o;
      o.tolerance = in.tolerance;
      o.force_scale = in.force_scale;
      o.max_iterations = in.max_iterations;
      o.max_seconds = in.max_seconds;
      o.uniform_mass = solver == Solver::dr_unit;
      o.progress = in.progress;
      return solve_static(model, state, o);
    }
    case Solver::newton:
    case Solver::ptc: {
      NewtonOptions o;
      o.continuation = solver == Solver::ptc;
      o.tolerance = in.tolerance;
      o.force_scale = in.force_scale;
      o.max_iterations = in.newton_iterations;
      o.max_seconds = in.max_seconds;
      o.progress = in.progress;
      o.cache = in.newton_cache;
      o.tangent_correction = in.tangent_correction;
      return solve_newton(model, state, o);
    }
    case Solver::rk4:
    case Solver::symplectic_euler: {
      DynamicsOptions o;
      o.method = std::string(solver_name(solver));
      o.dt = in.dt;
      o.steps = in.steps;
      o.tolerance = in.tolerance;
      o.force_scale = in.force_scale;
      o.stop_when_converged = in.stop_when_converged;
      o.max_seconds = in.max_seconds;
      o.progress = in.progress;
      o.on_check = in.on_check;
      o.settle_after = in.settle_after;
      return run_dynamics(model, state, o);
    }
  }
  throw std::logic_error("unknown solver");
}

}  // namespace membra
