#pragma once
// Inverse design (`membra design target FILE`): from a target surface to a resin stencil whose
// released form comes close to it. The method (docs/inverse_design.md): a resin density field
// with three parameters — mean, radial gradient, x/y anisotropy — started from the target's
// area (how much of the sheet must keep its stretched size) and its Gaussian curvature (where),
// laid out as a stencil of squares no smaller than the minimum feature, simulated with the
// ordinary runner (typed scenes, no file in the loop), and improved by a pattern search on the
// shape error until it stops falling or the budget is spent. The design file is read by
// io/design_reader.hpp.
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "membra/design/density_field.hpp"
#include "membra/design/shape_distance.hpp"
#include "membra/design/stencil_layout.hpp"
#include "membra/design/target_surface.hpp"
#include "membra/process/run.hpp"

namespace membra {

struct DesignSpec {
  std::filesystem::path file;
  std::string name = "design";
  TargetSpec target;
  double frame = 0.2;     // m, side of the square frame
  Vec2 lambda{1.5, 1.5};  // the pre-stretch; the natural sheet is frame / lambda
  int resolution = 25;    // particles along each side of the simulated sheet
  std::string material = "latex", resin = "epoxy";
  std::string resin_side = "top";  // the face the stencil is applied to
  bool bilayer = false;            // resin on that face only (the composite curls; bilayer.hpp)
  StencilLayout layout;            // cell 20 mm, minimum feature 4 mm
  // "adjoint": densities per cell optimised through the equilibrium's adjoint, then laid out as
  // a stencil (docs/inverse_design.md); "pattern_search": three density parameters searched
  // with a forward simulation of the stencil each.
  std::string method = "pattern_search";
  double density_cell = 0.01;  // m, adjoint: the design variables' cells
  double smoothing = 1e-4;     // adjoint: weight of the mean squared difference of neighbours
  int evaluations = 24;        // forward simulations (adjoint: forward + adjoint solves) at most
  double budget = 900.0;       // s of wall time at most
  Solver solver = Solver::static_fire;
  double tolerance = 1e-6;
  int increments = 10;  // of the release path
  // The scene every stencil is simulated in: sheet, stretch, an impregnate step at index 1 (its
  // resin, face and bilayer; the pattern is the stencil's) and release. Made by the reader.
  Scene scene;
};

// The density parameters: mean, radial gradient (r^2), anisotropy (x^2 - y^2), over the frame's
// half-size.
struct DensityParameters {
  double mean = 0.5, radial = 0.0, anisotropy = 0.0;
  double operator()(const Vec2& p, const Box2& frame) const;
};

struct DesignIteration {
  int index = 0;
  // "stencil": a stencil simulated and compared (rms and max after rigid alignment);
  // "density": an adjoint iterate, whose rms_error is the distance to the particles' own target
  // points (no max, pieces or share).
  std::string stage = "stencil";
  double objective = 0.0, gradient_norm = 0.0;  // density iterates
  DensityParameters parameters;
  double rms_error = 0.0, max_error = 0.0;  // % of the target's diameter
  double resin_share = 0.0;                 // of the sheet's area on the frame
  int pieces = 0;
  double seconds = 0.0;  // of this forward simulation
  bool best = false;     // the best so far when it was made
  std::string note;      // e.g. "did not converge"
};

struct DesignResult {
  DesignSpec spec;
  TargetSurface target;
  bool reachable = true;
  std::string message;            // why the target cannot be reached, when it cannot
  DensityParameters start, best;  // the start from mechanics, the best found
  Scene scene;                    // the best stencil's scene, as it was run
  Stencil stencil;
  RunResult run;                            // its forward simulation
  ShapeError error;                         // its distance to the target
  double rms_error = 0.0, max_error = 0.0;  // % of the target's diameter
  double flat_error = 0.0;  // rms % of a flat sheet of the target's footprint: the bar to beat
  std::vector<DesignIteration> history;
  double seconds = 0.0;
  // adjoint: the optimised densities, the form they release to (its rms error after rigid
  // alignment, before the stencil's pieces replace them), stage 1's reachability per cell and
  // why the optimiser stopped.
  std::string method;
  DensityField density;
  double density_rms_error = 0.0;
  Points density_form;             // the density design's released form (the stencil's triangles)
  ShapeError density_error;        // its distance to the target
  double unreachable_share = 0.0;  // of the cells: asking for a density outside [0, 1]
  double asks_min = 0.0, asks_max = 0.0;
  std::string stopped;
  // adjoint: the stencil calibration (area share of a cell's square -> the density it acts as).
  std::vector<double> calibration_share, calibration_density;
};

// A stencil laid out from `density` (frame coordinates), simulated as `membra run` would and
// compared with the target after rigid alignment.
struct StencilTrial {
  Stencil stencil;
  Scene scene;
  RunResult run;
  ShapeError error;
  double rms = std::numeric_limits<double>::infinity();  // % of the target's diameter
  double max = std::numeric_limits<double>::infinity();
  std::string note;  // why it is not a prediction ("did not converge", ...); empty if it is
};
StencilTrial try_stencil(const DesignSpec& spec, const TargetSurface& target,
                         const std::function<double(const Vec2&)>& density);
// Makes the trial the design's result: its scene, stencil, run, error and errors in %.
void adopt_stencil(StencilTrial&& trial, DesignResult& r);

// The scene that simulates `stencil` for a design: spec.scene with the stencil as its resin
// (without the impregnate step when the stencil is empty).
Scene stencil_scene(const DesignSpec& spec, const Stencil& stencil);

// Runs the design. `progress` (optional) is told of every forward simulation.
DesignResult run_design(const DesignSpec& spec,
                        const std::function<void(const DesignIteration&)>& progress = {});

}  // namespace membra
