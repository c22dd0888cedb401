#include "membra/process/bench.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "membra/measure/curvature.hpp"
#include "membra/model/benchmark_problem.hpp"
#include "membra/model/forces.hpp"
#include "membra/solve/dynamics.hpp"
#include "membra/solve/newton_solver.hpp"
#include "membra/solve/static_solver.hpp"

namespace membra {

std::vector<BenchRow> run_bench(const BenchOptions& o) {
  for (const auto& s : o.solvers)
    if (s != "static" && s != "dr_unit" && s != "newton" && s != "rk4")
      throw std::invalid_argument("unknown solver '" + s +
                                  "' (known: static, dr_unit, newton, rk4)");
  std::vector<BenchRow> rows;
  for (int n : o.sizes) {
    const BenchmarkProblem p = make_benchmark_problem(n);
    for (const auto& name : o.solvers) {
      State s = p.start;
      SolveReport r;
      if (name == "static" || name == "dr_unit") {
        StaticOptions so;
        so.tolerance = o.tolerance;
        so.max_iterations = 2'000'000'000L;
        so.max_seconds = o.budget;
        so.uniform_mass = name == "dr_unit";
        r = solve_static(p.model, s, so);
      } else if (name == "newton") {
        NewtonOptions no;
        no.tolerance = o.tolerance;
        no.max_iterations = 100000;
        no.max_seconds = o.budget;
        r = solve_newton(p.model, s, no);
      } else {
        // RK4 on the unit masses: the step at 60 % of its stability limit for the stiffest
        // particle, damping that critically damps the sheet's slowest bending-free mode.
        const auto g = stiffness_scaled_masses(p.model, s.x);
        const double omega_max = std::sqrt(*std::max_element(g.begin(), g.end()));
        Model damped = p.model;
        damped.velocity_damping = 2.0 * std::numbers::pi / n;
        DynamicsOptions d;
        d.method = "rk4";
        d.dt = 0.6 * 2.78 / omega_max;
        d.steps = 2'000'000'000L;
        d.tolerance = o.tolerance;
        d.max_seconds = o.budget;
        r = run_dynamics(damped, s, d);
      }
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
