#pragma once
// The pictures of a finished run: curvature.png, curvature_global.png (the window-averaged
// global form), stress.png, pattern.png, and when the scene asks for them curvature_map.png, the
// animation frames and their contact sheet, and each explored branch's curvature.png.
#include <string>

#include "membra/output/output_set.hpp"
#include "membra/output/run_files.hpp"
#include "membra/process/run.hpp"

namespace membra {

// Stages the pictures in `out` (not committed). Returns "" or, when no OpenGL is available, why
// the renders were skipped (pattern.png, drawn without OpenGL, is staged anyway).
std::string stage_run_pictures(const Scene& scene, const RunResult& r, const RunStaging& s,
                               OutputSet& out);

}  // namespace membra
