#pragma once
// `membra bench`: membra's solvers side by side on the benchmark problem P(n)
// (model/benchmark_problem.hpp), in one process, each with the same tolerance and wall-time
// budget. docs/performance.md has the results and the commands.
#include <array>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "membra/solve/solve_report.hpp"

namespace membra {

// The solvers `membra bench` runs by default (names of solve/solver.hpp's table): the
// equilibrium solvers and the paper's RK4, damped.
inline constexpr std::array<std::string_view, 4> kBenchSolvers = {"static", "dr_unit", "newton",
                                                                  "rk4"};

struct BenchOptions {
  std::vector<int> sizes{32, 64};
  // static: FIRE with stiffness-scaled masses (the default solver); dr_unit: the same with one
  // mass for all (plain dynamic relaxation); newton; rk4 (the paper's method, damped).
  std::vector<std::string> solvers{kBenchSolvers.begin(), kBenchSolvers.end()};
  double budget = 60.0;                         // s per solver and size
  double tolerance = 1e-6;                      // max |f| in units of k x spacing
  std::function<void(const std::string&)> log;  // one line per finished run
};

struct BenchRow {
  int n = 0;
  std::string solver;
  SolveReport report;         // wall_seconds, force_passes, iterations, residual, converged
  double energy = 0.0;        // potential energy at the end
  double angle_defect = 0.0;  // total over interior vertices, rad
};

// Runs every solver on every size. Throws std::invalid_argument for an unknown solver name.
std::vector<BenchRow> run_bench(const BenchOptions& options);

// Speed-up of `row` over `base` (base time / row time) when both converged; 0 otherwise.
double speedup(const BenchRow& row, const BenchRow& base);

}  // namespace membra
