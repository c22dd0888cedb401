#pragma once
// What a stencil of squares does, in the densities of the adjoint design: a cell whose square
// covers an area share a of it releases like a uniform resin density rho(a) — measured, not
// assumed. membra simulates uniform stencils (the same square in every cell) on the design's own
// sheet and finds the uniform density whose release has the same area (the metric, buckles and
// all). Between the samples the table is linear; the shares a stencil can have are 0, those of
// squares from the minimum feature up to a cell less the minimum feature, and 1 (a filled cell),
// so a wanted density rounds to the nearest of those (docs/inverse_design.md).
#include <functional>
#include <optional>
#include <vector>

#include "membra/design/design_spec.hpp"

namespace membra {

struct StencilCalibration {
  std::vector<double> share;     // area shares, increasing: 0, the sampled squares, 1
  std::vector<double> density;   // the uniform density each releases like (made monotone)
  std::vector<double> measured;  // the sampled squares' densities as measured (no end points)
  double min_share = 0.0, max_share = 1.0;  // of the smallest and largest square that can be cut
  bool cached = false;                      // read from spec.calibration_cache, not measured
  double density_of(double share) const;
  // The area share to lay out for density rho: the table inverted, rounded to what can be cut.
  double share_for(double rho) const;
};

// A store of calibrations by what they were measured on: `load` gives the one of (spec, samples)
// if it has it, `store` keeps one. A calibration depends only on the design's sheet, resin,
// stretch, layout and solver settings, not on its target, so designs on the same sheet share it.
struct CalibrationCache {
  std::function<std::optional<StencilCalibration>(const DesignSpec&, int samples)> load;
  std::function<void(const DesignSpec&, int samples, const StencilCalibration&)> store;
};

// `samples` squares from the smallest to the largest the layout allows, each a forward
// simulation at the design's resolution. `progress` is told each sample's (share, density).
// With spec.calibration_cache, a stored calibration is returned as it is (`cached` set).
StencilCalibration calibrate_stencil(const DesignSpec& spec, int samples = 4,
                                     const std::function<void(double, double)>& progress = {});

}  // namespace membra
