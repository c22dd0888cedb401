#include "membra/process/multilevel.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>
#include <string>

#include "membra/core/stopwatch.hpp"
#include "membra/geometry/grid_prolongation.hpp"
#include "membra/process/run.hpp"

namespace membra {
namespace {

int halved(int n) {
  return std::max(2, (n + 1) / 2);
}

// The grid of half the resolution along the longer side, the other side's spacing kept equal to
// it (cells stay as square as the scene's own).
std::pair<int, int> halved(const std::pair<int, int>& grid) {
  const auto [nx, ny] = grid;
  const bool x_longer = nx >= ny;
  const int a = halved(x_longer ? nx : ny), along = x_longer ? nx : ny, across = x_longer ? ny : nx;
  const int b =
      std::max(2, static_cast<int>(std::lround((a - 1.0) * (across - 1.0) / (along - 1.0))) + 1);
  return x_longer ? std::pair{a, b} : std::pair{b, a};
}

// True when the protocol's last step changes the sheet so that a solve follows (the release,
// grow, ...): only that step is carried from a coarser grid.
bool last_step_is_solved(const Scene& scene) {
  if (scene.protocol.empty()) return false;
  const ProtocolStep& last = scene.protocol.back();
  return !last.as<StretchStep>() && !last.as<ImpregnateStep>();
}

// Progress lines of a coarser level name its grid: "32x32 release 3/10".
ProgressFn level_progress(const ProgressFn& progress, int nx, int ny) {
  if (!progress) return {};
  const std::string prefix = std::to_string(nx) + "x" + std::to_string(ny) + " ";
  return [progress, prefix](const Progress& p) {
    Progress q = p;
    q.stage = prefix + q.stage;
    progress(q);
  };
}

// The scene's own grid: every step but the last as usual, the last solved once from `start`
// (the coarser grid's form, carried over) or, without one, its path followed.
RunResult run_finest(const Scene& scene, const RunResult* coarse, const ProgressFn& progress) {
  SceneRun run(scene, progress);
  for (size_t k = 0; k + 1 < scene.protocol.size(); ++k)
    if (!run.apply(scene.protocol[k])) return run.finish();
  if (coarse) {
    const Points start =
        prolongate(coarse->prepared.membrane.sheet.grid, coarse->prepared.membrane.state.x,
                   run.partial().prepared.membrane.sheet.grid);
    run.apply(scene.protocol.back(), &start);
    // A form that creeps into place past one solve's iterations but is nearly there (within
    // 100x the tolerance) is given two more solves before the path is followed instead.
    for (int more = 0; more < 2; ++more) {
      const SolveReport& s = run.partial().solve;
      if (s.converged || s.diverged || s.out_of_time ||
          !(s.residual_relative <= 100.0 * scene.simulation.tolerance))
        break;
      run.solve();
    }
  } else {
    run.apply(scene.protocol.back());
  }
  return run.finish();
}

}  // namespace

std::vector<std::pair<int, int>> multilevel_grids(const Scene& scene) {
  std::vector<std::pair<int, int>> grids{{scene.grid.nx, scene.grid.ny}};
  const int coarsest = scene.simulation.multilevel;
  if (coarsest <= 0 || !scene.simulation.is_static() || !last_step_is_solved(scene)) return grids;
  for (;;) {
    const std::pair<int, int> next = halved(grids.front());
    if (std::max(next.first, next.second) < coarsest) break;
    grids.insert(grids.begin(), next);
  }
  return grids;
}

Scene scene_at_resolution(const Scene& scene, int nx, int ny) {
  Scene s = scene;
  s.grid.nx = nx;
  s.grid.ny = ny;
  s.simulation.explore = 1;
  s.output.frames = 0;
  return s;
}

RunResult run_multilevel(const Scene& scene, const ProgressFn& progress) {
  const std::vector<std::pair<int, int>> grids = multilevel_grids(scene);
  if (grids.size() < 2) return run_scene(scene, progress);
  const Stopwatch clock;
  const auto [cx, cy] = grids[grids.size() - 2];
  // The coarser grid's run, itself multilevel down to the coarsest.
  const RunResult coarse =
      run_scene(scene_at_resolution(scene, cx, cy), level_progress(progress, cx, cy));
  std::vector<GridLevel> levels = coarse.levels;
  if (levels.empty()) levels.push_back({cx, cy, false, coarse.solve});
  // The budget is the whole run's: the finer grid gets what the coarser left.
  const auto left = [&] {
    Scene s = scene;
    if (s.simulation.max_seconds > 0.0)
      s.simulation.max_seconds = std::max(1e-3, s.simulation.max_seconds - clock.seconds());
    return s;
  };
  const bool carry = settled(coarse);
  RunResult r = run_finest(left(), carry ? &coarse : nullptr, progress);
  levels.push_back({scene.grid.nx, scene.grid.ny, carry, r.solve});
  // A form carried over that does not settle on the finer grid, or settles at a saddle: that
  // grid follows the path itself, as a run without levels would.
  if (carry && !settled(r) && !r.solve.diverged && !r.out_of_time) {
    r = run_finest(left(), nullptr, progress);
    levels.push_back({scene.grid.nx, scene.grid.ny, false, r.solve});
  }
  r.levels = std::move(levels);
  return r;
}

std::string multilevel_hint(const Scene& scene, double seconds) {
  if (scene.simulation.multilevel > 0 || seconds < 30.0) return "";
  if (std::max(scene.grid.nx, scene.grid.ny) < 64) return "";  // below, levels gain little
  Scene with = scene;
  with.simulation.multilevel = 16;
  if (multilevel_grids(with).size() < 2) return "";
  std::ostringstream line;
  line << "membra: tip: this " << scene.grid.nx << "x" << scene.grid.ny << " run took "
       << std::lround(seconds)
       << " s along its own path; --set simulation.multilevel=16 follows the path on coarser "
          "grids and settles this one from their form, often several times faster (a "
          "multistable pattern may then end in another of its stable forms; docs/solver.md)";
  return line.str();
}

std::string levels_summary(const std::vector<GridLevel>& levels) {
  std::ostringstream line;
  line << "multilevel:";
  for (size_t k = 0; k < levels.size(); ++k) {
    const GridLevel& l = levels[k];
    line << (k ? "; " : " ") << l.nx << "x" << l.ny << " "
         << (l.from_coarser ? "from the coarser grid" : "path") << ", " << l.solve.iterations
         << " iterations, " << std::fixed << std::setprecision(1) << l.solve.wall_seconds << " s"
         << (l.solve.converged ? "" : " (not converged)");
  }
  return line.str();
}

}  // namespace membra
