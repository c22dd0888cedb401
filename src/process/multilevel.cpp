#include "membra/process/multilevel.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>
#include <string>

#include "membra/core/input_error.hpp"
#include "membra/core/stopwatch.hpp"
#include "membra/core/units.hpp"
#include "membra/geometry/grid_prolongation.hpp"
#include "membra/geometry/mesh_prolongation.hpp"
#include "membra/process/cut_after_motion.hpp"
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

// True when the protocol's last step changes the sheet so that a solve follows along a path
// (the release, grow, ...): only that step is carried from a coarser level. Not a cut: it is
// solved at once, and it adds and removes particles after the start form would be laid on them.
bool last_step_is_solved(const Scene& scene) {
  if (scene.protocol.empty()) return false;
  const ProtocolStep& last = scene.protocol.back();
  return !last.as<StretchStep>() && !last.as<ImpregnateStep>() && !last.as<CutStep>();
}

// A level's name: "32x32" (a grid) or "max_edge 20 mm" (a mesh).
std::string level_name(const GridLevel& l) {
  if (l.max_edge <= 0.0) return std::to_string(l.nx) + "x" + std::to_string(l.ny);
  std::ostringstream name;
  name << "max_edge " << l.max_edge / units::mm << " mm";
  return name.str();
}

// Progress lines of a coarser level name it: "32x32 release 3/10".
ProgressFn level_progress(const ProgressFn& progress, const GridLevel& level) {
  if (!progress) return {};
  const std::string prefix = level_name(level) + " ";
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
    const Sheet& from = coarse->prepared.membrane.sheet;
    const Sheet& to = run.partial().prepared.membrane.sheet;
    const Points& x = coarse->prepared.membrane.state.x;
    const Points start = to.continuum() ? prolongate_on_mesh(from.model.reference, from.triangles,
                                                             x, to.model.reference, to.triangles)
                                        : prolongate(from.grid, x, to.grid);
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

// The levels of `scene` (grids or meshes), coarsest first, its own last.
std::vector<GridLevel> levels_of(const Scene& scene) {
  if (scene.model == SheetModel::continuum) return multilevel_meshes(scene);
  std::vector<GridLevel> levels;
  for (const auto& [nx, ny] : multilevel_grids(scene)) {
    GridLevel level;
    level.nx = nx, level.ny = ny;
    levels.push_back(level);
  }
  return levels;
}

// The scene at another level: its grid or its mesh.
Scene scene_at_level(const Scene& scene, const GridLevel& level) {
  Scene s = scene_at_resolution(scene, level.max_edge > 0.0 ? scene.grid.nx : level.nx,
                                level.max_edge > 0.0 ? scene.grid.ny : level.ny);
  if (level.max_edge > 0.0) {
    s.mesh.max_edge = level.max_edge;
    s.mesh.elements_across = level.elements_across;
  }
  return s;
}

// The level a run made, with its solve: the mesh's vertices as made.
GridLevel made(GridLevel level, const RunResult& r, bool from_coarser) {
  level.from_coarser = from_coarser;
  level.solve = r.solve;
  if (level.max_edge > 0.0) level.vertices = r.prepared.membrane.sheet.mesh.vertices;
  return level;
}

}  // namespace

std::vector<GridLevel> multilevel_meshes(const Scene& scene) {
  GridLevel own;
  own.max_edge = scene_max_edge(scene);
  own.elements_across = scene.mesh.elements_across;
  std::vector<GridLevel> levels{own};
  const int coarsest = scene.simulation.multilevel;
  if (coarsest <= 0 || !scene.simulation.is_static() || !last_step_is_solved(scene)) return levels;
  // A cut after the sheet moved is pulled back through each mesh's own form (cut_after_motion.hpp):
  // the coarser mesh's hole is not the finer one's, and its form carried over can fold a finer
  // mesh's triangles flat at the hole's rim (measured: NaN forces at the first iteration).
  if (any_cut_remeshes(scene)) return levels;
  const double longer = std::max(scene.grid.width, scene.grid.height);
  for (;;) {
    GridLevel next = levels.front();
    next.max_edge *= 2.0;
    next.elements_across = std::min(next.elements_across, std::max(2, next.elements_across / 2));
    if (longer / next.max_edge + 1.0 < coarsest) break;
    levels.insert(levels.begin(), next);
  }
  return levels;
}

std::vector<std::pair<int, int>> multilevel_grids(const Scene& scene) {
  std::vector<std::pair<int, int>> grids{{scene.grid.nx, scene.grid.ny}};
  const int coarsest = scene.simulation.multilevel;
  if (scene.model == SheetModel::continuum || coarsest <= 0 || !scene.simulation.is_static() ||
      !last_step_is_solved(scene))
    return grids;
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

bool has_levels(const Scene& scene) {
  return levels_of(scene).size() > 1;
}

RunResult run_multilevel(const Scene& scene, const ProgressFn& progress) {
  const std::vector<GridLevel> own_levels = levels_of(scene);
  if (own_levels.size() < 2) return run_scene(scene, progress);
  const Stopwatch clock;
  const GridLevel& coarser = own_levels[own_levels.size() - 2];
  const GridLevel& own = own_levels.back();
  // The coarser level's run, itself multilevel down to the coarsest. A continuum mesh the mesher
  // refuses at the coarser size (its narrowest feature is measured along boundaries sampled every
  // max_edge / 2, so a coarser level can find a sliver the scene's own missed) hands nothing on:
  // the scene's own mesh follows the path, and the run says why.
  RunResult coarse;
  try {
    coarse = run_scene(scene_at_level(scene, coarser), level_progress(progress, coarser));
  } catch (const InputError& e) {
    if (scene.model != SheetModel::continuum) throw;
    Scene without = scene;
    without.simulation.multilevel = 0;
    without.simulation.explore = 1;  // the outer run_scene explores, once
    RunResult r = run_scene(without, progress);
    r.warnings = {"simulation.multilevel: the coarser level (" + level_name(coarser) +
                  ") could not be meshed, so the scene's own mesh followed the path: " + e.what()};
    return r;
  }
  std::vector<GridLevel> levels = coarse.levels;
  if (levels.empty()) levels.push_back(made(coarser, coarse, false));
  // The budget is the whole run's: the finer grid gets what the coarser left.
  const auto left = [&] {
    Scene s = scene;
    if (s.simulation.max_seconds > 0.0)
      s.simulation.max_seconds = std::max(1e-3, s.simulation.max_seconds - clock.seconds());
    return s;
  };
  const bool carry = settled(coarse);
  RunResult r = run_finest(left(), carry ? &coarse : nullptr, progress);
  levels.push_back(made(own, r, carry));
  // A form carried over that does not settle on the finer grid, or settles at a saddle: that
  // grid follows the path itself, as a run without levels would.
  if (carry && !settled(r) && !r.solve.diverged && !r.out_of_time) {
    r = run_finest(left(), nullptr, progress);
    levels.push_back(made(own, r, false));
  }
  r.levels = std::move(levels);
  return r;
}

std::string multilevel_hint(const Scene& scene, double seconds) {
  if (scene.model == SheetModel::continuum || scene.simulation.multilevel > 0 || seconds < 30.0)
    return "";
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
    line << (k ? "; " : " ") << level_name(l);
    if (l.vertices > 0) line << " (" << l.vertices << " vertices)";
    line << " " << (l.from_coarser ? "from the coarser level" : "path") << ", "
         << l.solve.iterations << " iterations, " << std::fixed << std::setprecision(1)
         << l.solve.wall_seconds << " s" << (l.solve.converged ? "" : " (not converged)");
  }
  return line.str();
}

}  // namespace membra
