#pragma once
// The files of a finished run, staged in an OutputSet: the meshes and the stencil (the pictures
// are render/run_pictures.hpp's).
#include <vector>

#include "membra/output/output_set.hpp"
#include "membra/output/report_page.hpp"
#include "membra/process/run.hpp"

namespace membra {

// Colour ranges the user fixed (`--curvature-range`, `--stress-range`).
struct PictureOptions {
  std::vector<double> curvature_range;  // [lo, hi] in 1/mm^2, or empty for automatic
  std::vector<double> stress_range;     // [lo, hi] in MPa, or empty for automatic
};

// The share of the particles' |K| the default curvature colour range covers: the rest, sharp
// wrinkles between resin pieces, saturate instead of washing the form out to green.
inline constexpr double kCurvaturePercentile = 0.95;

// A run's values per particle in the outputs' units, and the colour ranges: symmetric about 0,
// so that green is flat / unstressed (curvature: kCurvaturePercentile of |K|, at least +-1e-6
// 1/mm^2, radius 1 m; stress: every value, at least +-1e-3 MPa), unless the user fixed them.
struct RunColors {
  std::vector<double> curvature;  // 1/mm^2
  std::vector<double> stress;     // MPa
  double k_lo = 0.0, k_hi = 0.0, s_lo = 0.0, s_hi = 0.0;
};
RunColors run_colors(const RunResult& r, const PictureOptions& opts);
// The two colourings of final.glb (curvature, stress) for report.html's legends.
std::vector<ColourScale> run_scales(const RunColors& c);

// Stages final.obj, final.ply (curvature colours, curvature and stress properties), final.glb
// (both colourings and both values, io/gltf.hpp), each
// explored branch's branches/N/final.obj and, when the scene has resin, the stencil pattern.svg
// and pattern.dxf, in `out` (not committed).
void stage_run_files(const Scene& scene, const RunResult& r, const PictureOptions& opts,
                     OutputSet& out);

}  // namespace membra
