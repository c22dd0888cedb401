#pragma once
// Every file of a finished run, as `membra run` and the Python module's Result.write stage them:
// report.json, and unless the run diverged the meshes, the stencil, the pictures and the page
// that shows them (report.html). One place,
// so that every front end writes the same files byte for byte.
#include <string>

#include "membra/output/output_set.hpp"
#include "membra/output/run_files.hpp"
#include "membra/process/run.hpp"

namespace membra {

struct StagedRun {
  bool report_only = false;  // the run diverged: a diverged state is no form, only its report
  std::string render_note;   // "" or why no PNG could be rendered (no OpenGL)
};

// Stages the run's files in `out` (not committed).
StagedRun stage_run_outputs(const Scene& scene, const RunResult& r, const PictureOptions& opts,
                            OutputSet& out);

}  // namespace membra
