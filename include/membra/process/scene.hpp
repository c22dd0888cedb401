#pragma once
// The typed scene: everything one reproducible membra run needs, in SI, with no file format in
// it (io/scene.hpp reads it from JSON). A sheet, pins, the simulation settings, the pictures, and
// the protocol: the ordered steps of the material process (docs/process.md).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "membra/geometry/grid_sheet.hpp"
#include "membra/measure/colormap.hpp"
#include "membra/model/pins.hpp"
#include "membra/model/sheet.hpp"
#include "membra/process/protocol.hpp"
#include "membra/solve/solver.hpp"

namespace membra {

// What the piece rests on once the frame lets go (docs/model.md, "On a table"): nothing (it
// floats), or a frictionless table at the frame's height that holds it against gravity G.
enum class Support { none, table };
const char* to_string(Support support);

// The continuum sheet's contact with itself (model/elements/self_contact.hpp,
// docs/model.md, "Self-contact"): `simulation.self_contact`.
struct SelfContactSpec {
  bool on = false;
  double gap = 1e-3;        // m, where the barrier begins
  double pressure = 1e3;    // Pa, its push per area at about half the gap is 4.3 times this
  double exclusion = 3e-3;  // m, points nearer than this on the natural sheet never touch
};

// How to simulate: the paper's K, G, T, D and the run length.
struct SimulationSpec {
  Solver solver = Solver::newton;  // solve/solver.hpp has the table
  double gravity = 9.81;           // G, m/s^2, acting along -z
  double dt = 1e-4;                // T, s
  double damping = 0.0;            // D, 1/s (force -D m v on every particle)
  long steps = 10000;              // time steps of a dynamic solver
  long max_iterations = 500000;    // iterations of the static solver
  double tolerance = 1e-6;         // relative to k_stretch x grid spacing
  // Tolerance of the intermediate increments of a path (release, grow, ...); the last increment
  // is solved to `tolerance`. Defaults to `tolerance` and is never tighter. Looser values save the
  // slow tails of the intermediate solves (2-3x) but can move the sheet onto another branch
  // (docs/performance.md, "Looser paths").
  double path_tolerance = 1e-6;
  bool stop_when_converged = true;
  // Time stepping: the simulated seconds over which each gradual step (release, grow, ...) is
  // applied, linearly, while the sheet moves; 0: at once, as the paper's tool lets go. A slow
  // ramp is the physical, slow process an equilibrium solver's increments stand for
  // (docs/forms.md). Must fit in the run: ramp_seconds <= steps x T.
  double ramp_seconds = 0.0;
  // Releases of the scene, each with another seeded imperfection, to find every stable form it
  // can take (explore.hpp); 1: the scene's own release only.
  int explore = 1;
  // Multilevel release (multilevel.hpp): the last step's path followed on grids halved down to
  // this many nodes along the longer side, each finer grid solved once from the coarser's form;
  // 0: off, the path followed on the scene's own grid.
  int multilevel = 0;
  // Wall-time budget of a run (each release of an exploration), s; 0: none. A run that
  // exhausts it stops unconverged and says so.
  double max_seconds = 0.0;
  // Newton on a continuum sheet: curve each step by the tangent correction
  // (solve/tangent_correction.hpp); false: straight steps, for comparison.
  bool tangent_correction = true;
  Support support = Support::none;
  SelfContactSpec self_contact;

  // True for the equilibrium solvers (static, newton), false for time stepping.
  bool is_static() const { return solver_info(solver).equilibrium; }
};

// What to draw.
struct OutputSpec {
  int frames = 0;           // animation frames to record (0: none), e.g. 24
  double azimuth = -60.0;   // camera, degrees around +z from +x
  double elevation = 35.0;  // camera, degrees above the sheet
  int image_width = 1200, image_height = 900;
  ColourMap colormap = ColourMap::diverging;  // of curvature and stress (measure/colormap.hpp)
};

// Which model of the sheet a scene simulates (docs/model.md): the paper's particle-spring
// lattice on a grid, or the continuum latex-resin shell on a mesh that follows the pattern.
enum class SheetModel { lattice, continuum };
const char* to_string(SheetModel model);

struct Scene {
  std::filesystem::path file;  // where it was read from (empty for in-memory scenes)
  std::string name;
  std::string description;
  SheetModel model = SheetModel::lattice;
  GridSpec grid;                      // SI; its resolution is the lattice's only
  MeshSpec mesh;                      // the continuum sheet's mesh (SI)
  SheetOptions sheet;                 // material in SI, K override in N/m
  std::string outline = "rectangle";  // or "disk": the ellipse inscribed in the rectangle
  int benchmark_n = 0;  // > 0: the model is the benchmark problem P(n) (dimensionless, SI as is)
  std::vector<PinSpec> pins;
  SimulationSpec simulation;
  OutputSpec output;
  std::vector<ProtocolStep> protocol;  // empty: one solve of the sheet as built
};

// The union of every impregnate step's pattern (nullptr if none), and the frame box (m) it lies
// in: the sheet stretched by all stretch steps.
// The continuum mesh's largest edge the scene asks for (m): its own, or the default.
double scene_max_edge(const Scene& scene);

PatternPtr scene_pattern(const Scene& scene);
// The union of the patterns coated on the underside only (bilayer steps on the bottom face) when
// `underside`, else of all the others: the two sheets of a stencil cut for both faces.
PatternPtr scene_pattern(const Scene& scene, bool underside);
Box2 scene_frame(const Scene& scene);

}  // namespace membra
