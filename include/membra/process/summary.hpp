#pragma once
// The end-of-run summary: energies, shape, curvature, stress, the stress at cuts and holes, the
// curvature map's match, and whether the end state is a minimum.
#include <functional>
#include <string>

#include "membra/process/run_result.hpp"

namespace membra {

// Fills the summary fields of `r` from its final state. `curvature_field` is the target of the
// scene's last curvature_map step (1/m^2 at a paper position), empty when it has none.
void summarize_run(RunResult& r, const std::function<double(const Vec2&)>& curvature_field);

// One line for a person: the form's height and its best-fit quadric, e.g. "form: 77.2 mm high, a
// synclastic quadric of radii 112 mm and 174 mm (the sheet 10.8 mm rms off it)".
std::string form_line(const RunResult& r);

}  // namespace membra
