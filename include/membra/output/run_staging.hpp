#pragma once
// What a finished run's outputs show, computed once before anything is written: values in the
// outputs' units, colour ranges and colourings, the global form, the patterns and their
// stencil outlines. The writers (run_files.hpp) and painters (render/run_pictures.hpp) only draw
// it.
#include <vector>

#include "membra/measure/colormap.hpp"
#include "membra/model/pattern.hpp"
#include "membra/model/pattern_stencil.hpp"
#include "membra/output/report_page.hpp"
#include "membra/process/run.hpp"

namespace membra {

// Colour ranges the user fixed (`--curvature-range`, `--stress-range`).
struct PictureOptions {
  std::vector<double> curvature_range;        // [lo, hi] in 1/m^2, or empty for automatic
  std::vector<double> stress_range;           // [lo, hi] in MPa, or empty for automatic
  ColourMap colormap = ColourMap::diverging;  // the scene's output.colormap (staging sets it)
};

// The share of the particles' |K| the default curvature colour range covers: the rest, sharp
// wrinkles between resin pieces, saturate instead of washing the form out to green.
inline constexpr double kCurvaturePercentile = 0.95;

// A run's values per particle in the outputs' units, and the colour ranges: symmetric about 0,
// so that green is flat / unstressed (curvature: kCurvaturePercentile of |K|, at least +-1e-6
// 1/m^2, radius 1 m; stress: every value, at least +-1e-3 MPa), unless the user fixed them.
struct RunColors {
  std::vector<double> curvature;  // 1/m^2
  std::vector<double> stress;     // MPa
  double k_lo = 0.0, k_hi = 0.0, s_lo = 0.0, s_hi = 0.0;
};
RunColors run_colors(const RunResult& r, const PictureOptions& opts);
// The two colourings of final.glb (curvature, stress) for report.html's legends.
std::vector<ColourScale> run_scales(const RunColors& c, ColourMap map);

// A colouring of values on one range (the range is its legend's).
struct Colouring {
  std::vector<Rgb> rgb;
  double lo = 0.0, hi = 0.0;
};

// What a run's files and pictures show, computed before any of them is written: the values and
// their colour ranges, the two colourings, the global form and its colouring, each explored
// branch's and each frame's colouring, the curvature map's target and measured colourings on the
// target's range, and the patterns on both faces (nullptr where none) with the stencil's outlines
// drawn from their geometry.
struct RunStaging {
  PictureOptions options;
  RunColors colors;
  std::vector<Rgb> curvature_rgb, stress_rgb;
  Points global_form;  // empty when it could not be formed
  Colouring global;
  std::vector<Colouring> branches;
  std::vector<Colouring> frames;  // on one stress range
  Colouring target, measured;     // a curvature map's, on the target's range
  PatternPtr top, bottom;
  Box2 frame;
  std::vector<CurveLoop> outlines, underside;
};
RunStaging prepare_run_staging(const Scene& scene, const RunResult& r, const PictureOptions& opts);

}  // namespace membra
