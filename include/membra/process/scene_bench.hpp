#pragma once
// `membra bench --scenes`: the equilibrium solvers side by side on real scenes (the forward
// examples at chosen resolutions), each run in full — every step, every increment — within a
// wall-time budget. docs/performance.md has the results and the commands.
#include <functional>
#include <string>
#include <vector>

#include "membra/process/mesh_convergence.hpp"
#include "membra/process/scene.hpp"

namespace membra {

struct SceneBenchRow {
  std::string scene;        // the scene's name
  std::string model;        // "lattice" or "continuum"
  int n = 0;                // the lattice's resolution n x n
  double max_edge = 0.0;    // m, the continuum's mesh as asked for
  int elements_across = 0;  // the continuum's mesh as asked for
  int vertices = 0;         // particles of the run's (finest) sheet
  std::string solver;
  SolveReport report;            // totals over the run: wall, iterations, factorizations, ...
  int increments = 0;            // path increments in all
  double height = 0.0;           // m, shape.height of the end state
  double total_curvature = 0.0;  // rad, curvature.total
  bool stable = false;           // the stability check of the end state
  FormReading form;              // the global form, for the mesh-convergence check
  bool over_budget = false;      // stopped by the budget (report.converged is false)
  std::string error;             // why the run failed (e.g. a mesh the mesher cannot make)
};

// Runs `scene` (already at its resolution) with `solver` until done or `budget` seconds.
SceneBenchRow bench_scene(Scene scene, Solver solver, double budget);

// Per scene, model and solver: the cost's growth with vertices, and on the continuum the
// mesh-convergence check of each converged run against the converged run at half its max_edge.
struct SceneBenchSummary {
  std::string scene, model, solver;
  double cost_exponent = 0.0;  // wall ~ vertices^p over the converged runs (0: fewer than two)
  int runs = 0;                // converged runs the exponent was fitted to
  struct Check {
    double max_edge = 0.0;  // m, the coarser mesh's
    MeshConvergence result;
  };
  std::vector<Check> checks;
};
std::vector<SceneBenchSummary> summarize_scene_bench(const std::vector<SceneBenchRow>& rows);

}  // namespace membra
