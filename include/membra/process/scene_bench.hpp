#pragma once
// `membra bench --scenes`: the equilibrium solvers side by side on real scenes (the forward
// examples at chosen resolutions), each run in full — every step, every increment — within a
// wall-time budget. docs/performance.md has the results and the commands.
#include <functional>
#include <string>
#include <vector>

#include "membra/process/scene.hpp"

namespace membra {

struct SceneBenchRow {
  std::string scene;  // the scene's name
  int n = 0;          // resolution n x n
  std::string solver;
  SolveReport report;            // totals over the run: wall, iterations, factorizations, ...
  int increments = 0;            // path increments in all
  double height = 0.0;           // m, shape.height of the end state
  double total_curvature = 0.0;  // rad, curvature.total
  bool stable = false;           // the stability check of the end state
  bool over_budget = false;      // stopped by the budget (report.converged is false)
};

// Runs `scene` (already at its resolution) with `solver` until done or `budget` seconds.
SceneBenchRow bench_scene(Scene scene, Solver solver, double budget);

}  // namespace membra
