#pragma once
// The pictures of a design: the best stencil's run pictures and comparison.png, the target
// (left) and the form moved onto it, coloured by its distance to the target (right).
#include <string>

#include "membra/design/inverse_design.hpp"
#include "membra/output/output_set.hpp"
#include "membra/output/run_files.hpp"

namespace membra {

// Stages the pictures in `out` (not committed). Returns "" or why the renders were skipped.
std::string stage_design_pictures(const DesignResult& d, const RunStaging& s, OutputSet& out);

}  // namespace membra
