#pragma once
// The files `membra design` writes: the stencil's scene, the target mesh, the report with the
// design's errors, and the run files of the best stencil (the pictures are
// render/design_pictures.hpp's).
#include <nlohmann/json.hpp>

#include "membra/io/design_reader.hpp"
#include "membra/output/output_set.hpp"
#include "membra/output/run_files.hpp"

namespace membra {

// The report: the run's report of the best stencil plus a "design" object (errors in % of the
// target's diameter, per iteration too).
nlohmann::json make_design_report(const DesignResult& d);

// Stages scene.json, target.obj, report.json, final.obj, final.ply, pattern.svg and pattern.dxf
// in `out` (not committed).
void stage_design_files(const DesignResult& d, const RunStaging& s, OutputSet& out);

}  // namespace membra
