#include "bench_command.hpp"

#include <omp.h>

#include <cstdio>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "membra/process/bench.hpp"
#include "membra/version.hpp"

namespace membra::cli {

int cmd_bench(const BenchArgs& args) {
  BenchOptions o;
  o.sizes = args.sizes;
  o.solvers = args.solvers;
  o.budget = args.budget;
  if (!args.quiet) o.log = [](const std::string& line) { std::cerr << line << "\n"; };
  const std::vector<BenchRow> rows = run_bench(o);

  // Speed-ups over membra's own RK4 and plain dynamic relaxation of the same size.
  auto base = [&](int n, const std::string& solver) -> const BenchRow* {
    for (const auto& r : rows)
      if (r.n == n && r.solver == solver) return &r;
    return nullptr;
  };
  if (args.json || !args.json_out.empty()) {
    nlohmann::json j;
    j["membra_version"] = kVersion;
    j["threads"] = omp_get_max_threads();
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
      for (const char* b : {"rk4", "dr_unit"})
        if (const BenchRow* br = base(r.n, b))
          row[std::string("speedup_vs_") + b] = speedup(r, *br);
      j["runs"].push_back(row);
    }
    if (!args.json_out.empty()) {
      std::ofstream out(args.json_out);
      out << j.dump(2) << "\n";
      if (!out) {
        std::cerr << "membra: error: cannot write " << args.json_out << "\n";
        return 4;
      }
    }
    if (args.json) {
      std::cout << j.dump(2) << "\n";
      return 0;
    }
  }
  std::printf("P(n), max|f| < %.0e, budget %.0f s per run, %d threads\n", o.tolerance, o.budget,
              omp_get_max_threads());
  std::printf("%5s %-8s %9s %11s %10s %10s %12s %10s %8s %8s\n", "n", "solver", "wall s",
              "force pass", "iters", "residual", "energy", "angle def", "x rk4", "x dr");
  for (const auto& r : rows) {
    auto ratio = [&](const char* b) {
      const BenchRow* br = base(r.n, b);
      const double s = br ? speedup(r, *br) : 0.0;
      static char buf[4][16];
      static int k = 0;
      char* out = buf[k++ % 4];
      if (s > 0.0)
        std::snprintf(out, 16, "%.1f", s);
      else
        std::snprintf(out, 16, "-");
      return out;
    };
    std::printf("%5d %-8s %9.2f %11ld %10ld %10.2e %12.6g %10.4f %8s %8s%s\n", r.n,
                r.solver.c_str(), r.report.wall_seconds, r.report.force_passes, r.report.iterations,
                r.report.residual, r.energy, r.angle_defect, ratio("rk4"), ratio("dr_unit"),
                r.report.diverged ? "  DIVERGED" : (r.report.converged ? "" : "  (budget)"));
  }
  return 0;
}

}  // namespace membra::cli
