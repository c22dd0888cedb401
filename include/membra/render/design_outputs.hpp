#pragma once
// What `membra design` writes beside the ordinary run outputs: the stencil's scene, the target
// mesh, the comparison picture and the report with the design's errors.
#include <string>

#include <nlohmann/json.hpp>

#include "membra/io/design_reader.hpp"
#include "membra/io/output_set.hpp"

namespace membra {

// The report: the run's report of the best stencil plus a "design" object (errors in % of the
// target's diameter, per iteration too).
nlohmann::json make_design_report(const DesignResult& d);

// Stages scene.json, target.obj, report.json, the run's outputs (final.obj, final.ply,
// pattern.svg/.dxf/.png, curvature.png, stress.png) and comparison.png: the target (left) and
// the form moved onto it, coloured by its distance to the target (right). Returns "" or why the
// pictures were skipped.
std::string stage_design_outputs(const DesignResult& d, OutputSet& out);

}  // namespace membra
