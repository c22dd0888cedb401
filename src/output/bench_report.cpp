#include "membra/output/bench_report.hpp"

#include "membra/version.hpp"

namespace membra {

const BenchRow* find_bench_row(const std::vector<BenchRow>& rows, int n,
                               const std::string& solver) {
  for (const auto& r : rows)
    if (r.n == n && r.solver == solver) return &r;
  return nullptr;
}

nlohmann::json bench_report(const std::vector<BenchRow>& rows, const BenchOptions& o, int threads) {
  nlohmann::json j;
  j["membra_version"] = kVersion;
  j["threads"] = threads;
  j["tolerance"] = o.tolerance;
  j["budget_seconds"] = o.budget;
  j["runs"] = nlohmann::json::array();
  for (const auto& r : rows) {
    nlohmann::json row = {{"n", r.n},
                          {"solver", r.solver},
                          {"converged", r.report.converged},
                          {"diverged", r.report.diverged},
                          {"wall_seconds", r.report.wall_seconds},
                          {"force_passes", r.report.force_passes},
                          {"iterations", r.report.iterations},
                          {"residual", r.report.residual},
                          {"energy", r.energy},
                          {"angle_defect", r.angle_defect}};
    // Speed-ups over membra's own RK4 and plain dynamic relaxation of the same size.
    for (const char* b : {"rk4", "dr_unit"})
      if (const BenchRow* br = find_bench_row(rows, r.n, b))
        row[std::string("speedup_vs_") + b] = speedup(r, *br);
    j["runs"].push_back(row);
  }
  return j;
}

nlohmann::json scene_bench_report(const std::vector<SceneBenchRow>& rows) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& r : rows)
    a.push_back({{"scene", r.scene},
                 {"model", r.model},
                 {"n", r.n},
                 {"max_edge_mm", r.max_edge * 1e3},
                 {"elements_across", r.elements_across},
                 {"vertices", r.vertices},
                 {"classification", r.form.classification},
                 {"global_height_mm", r.form.height * 1e3},
                 {"global_total_K", r.form.total_curvature},
                 {"energy", r.form.energy},
                 {"solver", r.solver},
                 {"converged", r.report.converged},
                 {"over_budget", r.over_budget},
                 {"error", r.error},
                 {"stable", r.stable},
                 {"wall_seconds", r.report.wall_seconds},
                 {"iterations", r.report.iterations},
                 {"factorizations", r.report.factorizations},
                 {"negative_curvature_steps", r.report.negative_curvature_steps},
                 {"lanczos_steps", r.report.lanczos_steps},
                 {"tangent_corrections", r.report.tangent_corrections},
                 {"increments", r.increments},
                 {"residual_relative", r.report.residual_relative},
                 {"height_mm", r.height * 1e3},
                 {"total_curvature_rad", r.total_curvature}});
  return a;
}

nlohmann::json scene_summary_report(const std::vector<SceneBenchSummary>& summaries) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& s : summaries) {
    nlohmann::json checks = nlohmann::json::array();
    for (const auto& c : s.checks)
      checks.push_back({{"max_edge_mm", c.max_edge * 1e3},
                        {"same_classification", c.result.same_classification},
                        {"curvature_change", c.result.curvature_change},
                        {"height_change", c.result.height_change},
                        {"energy_change", c.result.energy_change},
                        {"passes", c.result.passes()}});
    a.push_back({{"scene", s.scene},
                 {"model", s.model},
                 {"solver", s.solver},
                 {"cost_exponent", s.cost_exponent},
                 {"runs", s.runs},
                 {"mesh_convergence", checks}});
  }
  return a;
}

}  // namespace membra
