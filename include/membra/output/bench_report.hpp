#pragma once
// `membra bench --json`: the runs of the solvers on P(n) as JSON, with the speed-ups over RK4 and
// plain dynamic relaxation of the same size (docs/cli.md, "membra bench").
#include <vector>

#include <nlohmann/json.hpp>

#include "membra/process/bench.hpp"
#include "membra/process/scene_bench.hpp"

namespace membra {

// The row of `solver` at size n, or nullptr.
const BenchRow* find_bench_row(const std::vector<BenchRow>& rows, int n, const std::string& solver);

nlohmann::json bench_report(const std::vector<BenchRow>& rows, const BenchOptions& options,
                            int threads);

// `membra bench --scenes`: the scene runs as a JSON array (the "scenes" key of the report), with
// units in the key names.
nlohmann::json scene_bench_report(const std::vector<SceneBenchRow>& rows);
// Per scene, model and solver: "cost_exponent" (wall ~ vertices^p), "runs" it was fitted to, and
// "mesh_convergence" (each check's coarser "max_edge_mm", "same_classification",
// "curvature_change", "height_change", "energy_change" as fractions, and "passes").
nlohmann::json scene_summary_report(const std::vector<SceneBenchSummary>& summaries);

}  // namespace membra
