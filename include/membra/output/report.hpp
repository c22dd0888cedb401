#pragma once
// report.json: the numbers of a run, each with its unit (docs/cli.md, "membra run").
#include <nlohmann/json.hpp>

#include "membra/process/run.hpp"

namespace membra {

// The report of a finished (or diverged) run. Keys: converged, residual, residual_relative,
// iterations, force_passes, wall_seconds, particles, springs, pinned, energy, energy_parts,
// shape.height, ... and `units`, which maps each key to its unit.
nlohmann::json make_report(const Scene& scene, const RunResult& result);

}  // namespace membra
