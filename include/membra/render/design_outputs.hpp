#pragma once
// Every file of a finished design, as `membra design` and the Python module's write stage them:
// the design's files (output/design_files.hpp), its pictures (design_pictures.hpp) and report.html.
#include <string>

#include "membra/design/inverse_design.hpp"
#include "membra/output/output_set.hpp"

namespace membra {

// Stages them in `out` (not committed). Returns "" or why the renders were skipped.
std::string stage_design_outputs(const DesignResult& d, OutputSet& out);

}  // namespace membra
