#include "bench_command.hpp"

#include <omp.h>

#include <cstdio>
#include <fstream>
#include <iostream>

#include "membra/io/bench_report.hpp"
#include "membra/process/bench.hpp"

namespace membra::cli {
namespace {

// "3.2" or "-" when either run did not converge.
std::string ratio(const std::vector<BenchRow>& rows, const BenchRow& r, const char* base) {
  const BenchRow* br = find_bench_row(rows, r.n, base);
  const double s = br ? speedup(r, *br) : 0.0;
  char out[16];
  if (s > 0.0)
    std::snprintf(out, sizeof out, "%.1f", s);
  else
    std::snprintf(out, sizeof out, "-");
  return out;
}

void print_table(const std::vector<BenchRow>& rows, const BenchOptions& o) {
  std::printf("P(n), max|f| < %.0e, budget %.0f s per run, %d threads\n", o.tolerance, o.budget,
              omp_get_max_threads());
  std::printf("%5s %-8s %9s %11s %10s %10s %12s %10s %8s %8s\n", "n", "solver", "wall s",
              "force pass", "iters", "residual", "energy", "angle def", "x rk4", "x dr");
  for (const auto& r : rows)
    std::printf("%5d %-8s %9.2f %11ld %10ld %10.2e %12.6g %10.4f %8s %8s%s\n", r.n,
                r.solver.c_str(), r.report.wall_seconds, r.report.force_passes, r.report.iterations,
                r.report.residual, r.energy, r.angle_defect, ratio(rows, r, "rk4").c_str(),
                ratio(rows, r, "dr_unit").c_str(),
                r.report.diverged ? "  DIVERGED" : (r.report.converged ? "" : "  (budget)"));
}

}  // namespace

int cmd_bench(const BenchArgs& args) {
  BenchOptions o;
  o.sizes = args.sizes;
  o.solvers = args.solvers;
  o.budget = args.budget;
  if (!args.quiet) o.log = [](const std::string& line) { std::cerr << line << "\n"; };
  const std::vector<BenchRow> rows = run_bench(o);
  if (args.json || !args.json_out.empty()) {
    const nlohmann::json j = bench_report(rows, o, omp_get_max_threads());
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
  print_table(rows, o);
  return 0;
}

}  // namespace membra::cli
