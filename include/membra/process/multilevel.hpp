#pragma once
// Multilevel release: a scene on a fine grid follows its last step's path (the release) on a
// grid of half its resolution — recursively, down to `simulation.multilevel` nodes along the
// longer side — and each finer grid starts from the coarser grid's end form (carried over by
// geometry/grid_prolongation.hpp) with one solve of the step's full change. The path, where the
// sheet picks its branch, is followed where an iteration is cheap; the fine grid only settles
// the form's detail near it (docs/solver.md, "Multilevel release"). On the continuum model the
// levels are meshes of doubled max_edge, carried over by geometry/mesh_prolongation.hpp.
#include <string>
#include <utility>
#include <vector>

#include "membra/core/progress.hpp"
#include "membra/process/run_result.hpp"
#include "membra/process/scene.hpp"

namespace membra {

// The grids a run of `scene` passes through, coarsest first, the scene's own last: a single
// entry when multilevel does not apply (simulation.multilevel 0, a time-stepping solver, a
// protocol whose last step needs no solve, or a grid too small to halve above the coarsest).
std::vector<std::pair<int, int>> multilevel_grids(const Scene& scene);

// The scene on an nx x ny grid, as the coarser levels run it: the same sheet, pattern and
// protocol; no frames and no exploration.
Scene scene_at_resolution(const Scene& scene, int nx, int ny);

// The meshes a continuum run of `scene` passes through, coarsest first, its own last: max_edge
// doubled and elements_across halved (at least 2) per level, while the sheet's longer side holds
// at least simulation.multilevel - 1 of those edges. A single entry as multilevel_grids says.
std::vector<GridLevel> multilevel_meshes(const Scene& scene);

// True when a run of `scene` passes through coarser levels: grids (multilevel_grids) on the
// lattice; on the continuum, meshes of doubled max_edge and halved elements_across (at least 2)
// while the sheet's longer side holds at least simulation.multilevel - 1 of those edges.
bool has_levels(const Scene& scene);

// Runs `scene` through its levels (multilevel_grids, or the continuum's meshes). A coarser level
// that ends unconverged or unstable hands nothing on: the scene's own grid then follows the path
// itself. The result's `levels` lists every grid's run.
RunResult run_multilevel(const Scene& scene, const ProgressFn& progress);

// One line for people: "multilevel: 32x32 path, 745 iterations, 15.1 s; 64x64 from 32x32, ...".
std::string levels_summary(const std::vector<GridLevel>& levels);

// A tip after a long run without levels: when `scene` has none (simulation.multilevel 0), a grid
// of at least 64 nodes along its longer side whose last step multilevel could take from 16, and
// the run took `seconds` >= 30, a line that says how; empty otherwise.
std::string multilevel_hint(const Scene& scene, double seconds);

}  // namespace membra
