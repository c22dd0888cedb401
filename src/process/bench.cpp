#include "membra/process/bench.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "membra/measure/curvature.hpp"
#include "membra/model/benchmark_problem.hpp"
#include "membra/model/forces.hpp"
#include "membra/solve/solver.hpp"
#include "membra/solve/static_solver.hpp"

namespace membra {

namespace {

// RK4 on the unit masses: the step at 60 % of its stability limit for the stiffest particle,
// damping that critically damps the sheet's slowest bending-free mode.
SolveReport run_damped_rk4(const BenchmarkProblem& p, int n, State& s, SolverSettings settings) {
  const auto g = stiffness_scaled_masses(p.model, s.x);
  const double omega_max = std::sqrt(*std::max_element(g.begin(), g.end()));
  Model damped = p.model;
  damped.velocity_damping = 2.0 * std::numbers::pi / n;
  settings.dt = 0.6 * 2.78 / omega_max;
  settings.steps = 2'000'000'000L;
  return solve_with(Solver::rk4, damped, s, settings);
}

}  // namespace

std::vector<BenchRow> run_bench(const BenchOptions& o) {
  std::vector<Solver> solvers;
  for (const auto& name : o.solvers) {
    const auto solver = solver_from_name(name);
    if (!solver || (!solver_info(*solver).equilibrium && *solver != Solver::rk4)) {
      std::string known;
      for (const SolverInfo& k : solver_table())
        if (k.equilibrium || k.id == Solver::rk4)
          known += (known.empty() ? "" : ", ") + std::string(k.name);
      throw std::invalid_argument("unknown solver '" + name + "' (known: " + known + ")");
    }
    solvers.push_back(*solver);
  }
  std::vector<BenchRow> rows;
  for (int n : o.sizes) {
    const BenchmarkProblem p = make_benchmark_problem(n);
    for (const Solver solver : solvers) {
      State s = p.start;
      SolverSettings settings;
      settings.tolerance = o.tolerance;
      settings.max_iterations = 2'000'000'000L;
      settings.newton_iterations = 100000;
      settings.max_seconds = o.budget;
      const SolveReport r = solver == Solver::rk4 ? run_damped_rk4(p, n, s, settings)
                                                  : solve_with(solver, p.model, s, settings);
      const std::string name(solver_name(solver));
      BenchRow row{n, name, r, potential_energy(p.model, s.x),
                   r.diverged ? 0.0 : gaussian_curvature(s.x, p.triangles).total};
      if (o.log) {
        std::ostringstream line;
        line << "P(" << n << ") " << name << ": " << r.message << " in " << r.wall_seconds << " s";
        o.log(line.str());
      }
      rows.push_back(row);
    }
  }
  return rows;
}

double speedup(const BenchRow& row, const BenchRow& base) {
  if (!row.report.converged || !base.report.converged || row.report.wall_seconds <= 0.0) return 0.0;
  return base.report.wall_seconds / row.report.wall_seconds;
}

}  // namespace membra
