#include "membra/process/scene_bench.hpp"

#include <stdexcept>
#include <variant>

#include "membra/process/run.hpp"

namespace membra {
namespace {

// Thrown from the progress callback to stop a run at its budget.
struct OverBudget : std::runtime_error {
  OverBudget() : std::runtime_error("over budget") {}
};

int path_increments(const Scene& scene) {
  int n = 0;
  for (const ProtocolStep& p : scene.protocol)
    std::visit(
        [&](const auto& s) {
          if constexpr (requires { s.path.increments; }) n += s.path.increments;
        },
        p.step);
  return n;
}

}  // namespace

SceneBenchRow bench_scene(Scene scene, Solver solver, double budget) {
  scene.simulation.solver = solver;
  SceneBenchRow row;
  row.scene = scene.name;
  row.n = scene.grid.nx;
  row.solver = std::string(solver_name(solver));
  if (scene.simulation.multilevel > 0)  // "newton/ml32": multilevel down to 32 nodes
    row.solver += "/ml" + std::to_string(scene.simulation.multilevel);
  row.increments = path_increments(scene);
  const Stopwatch clock;
  try {
    const RunResult r = run_scene(scene, [&](const Progress&) {
      if (clock.seconds() > budget) throw OverBudget();
    });
    row.report = r.solve;
    // A multilevel run's work is every grid's (its `solve` is the finest grid's, the last).
    if (!r.levels.empty()) {
      row.report = {};
      for (const GridLevel& l : r.levels) accumulate(row.report, l.solve);
    }
    row.height = r.shape.height;
    row.total_curvature = r.curvature.total;
    row.stable = r.stability.checked && r.stability.stable;
  } catch (const OverBudget&) {
    row.over_budget = true;
    row.report.converged = false;
  }
  row.report.wall_seconds = clock.seconds();
  return row;
}

}  // namespace membra
