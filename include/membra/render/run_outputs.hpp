#pragma once
// Everything `membra run` writes for a finished run: meshes, stencil and pictures.
#include <string>
#include <vector>

#include "membra/io/output_set.hpp"
#include "membra/process/run.hpp"

namespace membra {

struct PictureOptions {
  std::vector<double> curvature_range;  // [lo, hi] in 1/mm^2, or empty for automatic
  std::vector<double> stress_range;     // [lo, hi] in MPa, or empty for automatic
};

// Stages final.obj, final.ply, pattern.svg/.dxf/.png (when the scene has resin),
// curvature.png, stress.png and the animation frames in `out` (not committed). Returns "" or,
// when no OpenGL is available, why the PNG renders were skipped (the rest is still staged).
std::string stage_run_outputs(const Scene& scene, const RunResult& r, const PictureOptions& opts,
                              OutputSet& out);

}  // namespace membra
