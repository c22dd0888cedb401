#pragma once
// What a design gives (docs/inverse_design.md): the best stencil, its simulated form and errors,
// every iteration, and for the adjoint method its densities, their own form and the stencil
// calibration.
#include <limits>
#include <string>
#include <vector>

#include "membra/design/density_field.hpp"
#include "membra/design/design_spec.hpp"
#include "membra/design/shape_distance.hpp"
#include "membra/design/stencil_layout.hpp"
#include "membra/design/target_surface.hpp"
#include "membra/process/run_result.hpp"

namespace membra {

// The density parameters: mean, radial gradient (r^2), anisotropy (x^2 - y^2), over the frame's
// half-size.
struct DensityParameters {
  double mean = 0.5, radial = 0.0, anisotropy = 0.0;
  double stretch = 1.0;  // the pre-stretch's factor (design_stretch.hpp; 1: as the file says)
  double darts = 1.0;    // darts layout: their width over what the target's metric asks
  double operator()(const Vec2& p, const Box2& frame) const {
    const Vec2 c = 0.5 * (frame.min + frame.max), h = 0.5 * (frame.max - frame.min);
    const double u = (p.x() - c.x()) / h.x(), v = (p.y() - c.y()) / h.y();
    // r^2 - 1/2 and x^2 - y^2 average to about zero over the frame: the mean stays the mean.
    return mean + radial * (u * u + v * v - 0.5) + anisotropy * (u * u - v * v);
  }
};

struct DesignIteration {
  int index = 0;
  // "stencil": a stencil simulated and compared (rms and max after rigid alignment);
  // "density": an adjoint iterate, whose rms_error is the distance to the particles' own target
  // points (no max, pieces or share); "pieces": the same for stage 3's piece sizes.
  std::string stage = "stencil";
  bool adjoint_iterate() const { return stage == "density" || stage == "pieces"; }
  double objective = 0.0, gradient_norm = 0.0;  // density iterates
  DensityParameters parameters;
  double rms_error = 0.0, max_error = 0.0;  // % of the target's diameter
  double resin_share = 0.0;                 // of the sheet's area on the frame
  int pieces = 0;
  double seconds = 0.0;  // of this forward simulation
  double scale = 1.0;    // adjoint stencils: the multiple of the designed densities laid out
  bool best = false;     // the best so far when it was made
  std::string note;      // e.g. "did not converge"
};

struct DesignResult {
  DesignSpec spec;
  TargetSurface target;
  bool reachable = true;
  // Why the target cannot be reached, when it cannot, and what else the design has to say
  // (the CLI's note: line); add_message appends a sentence.
  std::string message;
  void add_message(const std::string& sentence) {
    message += (message.empty() ? "" : " ") + sentence;
  }
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
  double density_rms_error = std::numeric_limits<double>::quiet_NaN();  // NaN: no equilibrium
  Points density_form;             // the density design's released form (the stencil's triangles)
  ShapeError density_error;        // its distance to the target
  double unreachable_share = 0.0;  // of the cells: asking for a density outside [0, 1]
  double asks_min = 0.0, asks_max = 0.0;
  std::string stopped;
  // adjoint: the stencil calibration (area share of a cell's square -> the density it acts as).
  std::vector<double> calibration_share, calibration_density;
  bool calibration_cached = false;  // read from the calibration cache, not measured this run
};

}  // namespace membra
