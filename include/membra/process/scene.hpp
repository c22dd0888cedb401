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
#include "membra/model/added_springs.hpp"
#include "membra/model/field_spec.hpp"
#include "membra/model/grow.hpp"
#include "membra/model/membrane.hpp"
#include "membra/model/pattern.hpp"
#include "membra/model/pattern_spec.hpp"
#include "membra/model/pins.hpp"
#include "membra/model/sheet.hpp"
#include "membra/solve/solver.hpp"

namespace membra {

// How to simulate: the paper's K, G, T, D and the run length.
struct SimulationSpec {
  Solver solver = Solver::static_fire;  // solve/solver.hpp has the table
  double gravity = 9.81;                // G, m/s^2, acting along -z
  double dt = 1e-4;                     // T, s
  double damping = 0.0;                 // D, 1/s (force -D m v on every particle)
  long steps = 10000;                   // time steps of a dynamic solver
  long max_iterations = 500000;         // iterations of the static solver
  double tolerance = 1e-6;              // relative to k_stretch x grid spacing
  // Tolerance of the intermediate increments of a path (release, grow, ...); the last increment
  // is solved to `tolerance`. Defaults to `tolerance` and is never tighter. Looser values save the
  // slow tails of the intermediate solves (2-3x) but can move the sheet onto another branch
  // (docs/performance.md, "Looser paths").
  double path_tolerance = 1e-6;
  bool stop_when_converged = true;

  // True for the equilibrium solvers (static, newton), false for time stepping.
  bool is_static() const { return solver_info(solver).equilibrium; }
};

// What to draw.
struct OutputSpec {
  int frames = 0;           // animation frames to record (0: none), e.g. 24
  double azimuth = -60.0;   // camera, degrees around +z from +x
  double elevation = 35.0;  // camera, degrees above the sheet
  int image_width = 1200, image_height = 900;
};

// One step of the process (docs/process.md), in SI.
struct ProtocolStep {
  enum class Kind {
    stretch,
    impregnate,
    release,
    load,
    grow,
    add_springs,
    cut,
    curvature_map
  } kind = Kind::stretch;
  std::string pointer;  // "/protocol/2", for messages
  // stretch
  Vec2 lambda{1.0, 1.0};
  FrameEdges hold;  // edges the frame holds
  // impregnate
  PatternPtr pattern;
  PatternSpec pattern_spec;  // its description, to write the scene back
  Material resin;
  int resin_side = +1;   // +1 top, -1 bottom
  bool bilayer = false;  // resin on that face only: the composite curls on release
  // release, grow, add_springs
  int increments = 10;           // static solver: steps of the quasi-static path
  double perturbation = 0.2e-3;  // m, symmetry-breaking bump
  std::uint64_t seed = 1;
  // grow (its factor and region as described, to write the scene back)
  GrowSpec grow;
  FieldSpec grow_factor;
  std::optional<PatternSpec> grow_region;
  // add_springs (stiffness 0: the sheet's own stretch stiffness)
  AddSpringsSpec add;
  PatternSpec add_region;
  // curvature_map: the target Gaussian curvature (1/m^2) at a paper position (m)
  std::function<double(const Vec2&)> curvature;
  FieldSpec curvature_spec;  // 1/mm^2, as described
  // cut: a polyline (frame coordinates, m) and/or a hole
  std::vector<Vec2> cut_line;
  PatternPtr hole;
  std::optional<PatternSpec> hole_spec;
  // load
  std::optional<double> gravity;  // m/s^2 along -z
  std::vector<PinSpec> pins;
};

struct Scene {
  std::filesystem::path file;  // where it was read from (empty for in-memory scenes)
  std::string name;
  std::string description;
  GridSpec grid;                      // SI
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
PatternPtr scene_pattern(const Scene& scene);
Box2 scene_frame(const Scene& scene);

}  // namespace membra
