#pragma once
// What a design file asks for (`membra design target FILE`, docs/inverse_design.md): the target,
// the frame and its pre-stretch, the sheet, the resin and its stencil's limits, the method and
// its budget, and the scene every stencil is simulated in. Read by io/design_reader.hpp.
#include <filesystem>
#include <memory>
#include <string>

#include "membra/design/stencil_layout.hpp"
#include "membra/design/target_surface.hpp"
#include "membra/process/scene.hpp"
#include "membra/solve/solver.hpp"

namespace membra {

struct CalibrationCache;  // design/stencil_calibration.hpp

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
  // adjoint, stage 1: how the target is laid over the frame, "conformal" (its conformal
  // flattening) or "projection" (straight down onto its footprint); target_correspondence.hpp.
  std::string flattening = "conformal";
  // adjoint, stage 3: stencils simulated from flat — the calibrated one, then the wanted
  // densities scaled by 0.85, 1.15, 0.7, 1.3 — the best that settles is the design's.
  int stencil_trials = 5;
  int piece_evaluations = 20;   // adjoint: stage 3's evaluations on the best trial's piece sizes
  int evaluations = 24;         // forward simulations (adjoint: forward + adjoint solves) at most
  bool search_stretch = false;  // pattern search: the pre-stretch is a fourth parameter
  double budget = 900.0;        // s of wall time at most
  Solver solver = Solver::newton;
  double tolerance = 1e-6;
  int increments = 10;  // of the release path
  // The scene every stencil is simulated in: sheet, stretch, an impregnate step at index 1 (its
  // resin, face and bilayer; the pattern is the stencil's) and release. Made by the reader.
  Scene scene;
  // Where the adjoint method keeps stencil calibrations between designs (none: measured every
  // time). `membra design` sets one on disk (output/calibration_store.hpp).
  std::shared_ptr<const CalibrationCache> calibration_cache;
};

}  // namespace membra
