#include "bench_command.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "membra/core/input_error.hpp"
#include "membra/io/scene.hpp"
#include "membra/output/bench_report.hpp"
#include "membra/process/bench.hpp"
#include "membra/process/scene_bench.hpp"

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

// A number in full ("6.666666666666667"), so that a mesh and its half compare exactly.
std::string exact(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// The --set overrides of each run of a scene file: the lattice at every size, the continuum on
// its default mesh at every scale (max_edge and the chord tolerance times it, elements_across
// over it).
std::vector<std::vector<std::string>> scene_variants(const BenchArgs& args,
                                                     const std::string& file) {
  std::vector<std::vector<std::string>> out;
  for (const std::string& model : args.scene_models) {
    if (model == "lattice") {
      for (int n : args.scene_sizes)
        out.push_back({"model=lattice",
                       "sheet.resolution=[" + std::to_string(n) + "," + std::to_string(n) + "]"});
    } else if (model == "continuum") {
      const Scene own = load_scene(file, {"model=continuum"});
      const double edge = scene_max_edge(own);
      for (double scale : args.scene_mesh_scales) {
        // Within what a scene accepts (src/io/scene.cpp), so a small scale cannot end the bench.
        const long across = std::clamp(std::lround(own.mesh.elements_across / scale), 1L, 64L);
        // The chords of curved outlines scale too: a half-size mesh of a 1 mm sliver needs
        // elements that the default chord tolerance calls too small (continuum_sheet.cpp).
        out.push_back({"model=continuum", "sheet.mesh.max_edge=" + exact(edge * scale * 1e3),
                       "sheet.mesh.elements_across=" + std::to_string(across),
                       "sheet.mesh.tolerance=" +
                           exact(std::clamp(own.mesh.tolerance * scale * 1e3, 1e-4, 1.0))});
      }
    } else {
      throw InputError("--scene-models", "'" + model + "' is no model (lattice, continuum)");
    }
  }
  return out;
}

// Every scene file on every model, size and mesh with every solver, one line logged per run.
std::vector<SceneBenchRow> run_scene_bench(const BenchArgs& args) {
  std::vector<Solver> solvers;
  for (const std::string& name : args.scene_solvers) {
    const auto solver = solver_from_name(name);
    if (!solver || !solver_info(*solver).equilibrium)
      throw InputError("--scene-solvers", "'" + name + "' is no equilibrium solver");
    solvers.push_back(*solver);
  }
  std::vector<SceneBenchRow> rows;
  for (const std::string& file : args.scene_files)
    for (std::vector<std::string> sets : scene_variants(args, file))
      for (int levels : args.scene_multilevel) {
        sets.push_back("simulation.multilevel=" + std::to_string(levels));
        const Scene scene = load_scene(file, sets);
        sets.pop_back();
        for (Solver solver : solvers) {
          rows.push_back(bench_scene(scene, solver, args.budget));
          const SceneBenchRow& r = rows.back();
          if (!args.quiet)
            std::cerr << r.scene << " " << r.model << " " << r.vertices << " vertices " << r.solver
                      << ": " << r.report.wall_seconds << " s" << (r.over_budget ? " (budget)" : "")
                      << (r.error.empty() ? "" : " (error: " + r.error + ")") << "\n";
        }
      }
  return rows;
}

void print_scene_table(const std::vector<SceneBenchRow>& rows, double budget) {
  std::printf("\nscenes, full runs, budget %.0f s per run\n", budget);
  std::printf("%-22s %-9s %9s %-12s %8s %8s %7s %5s %6s %9s %10s %8s %-12s\n", "scene", "model",
              "mesh", "solver", "wall s", "iters", "factor", "incr", "conv", "resid", "height mm",
              "total K", "global form");
  for (const auto& r : rows) {
    char mesh[32];
    if (r.max_edge > 0.0)
      std::snprintf(mesh, sizeof mesh, "%.3g/%d", r.max_edge * 1e3, r.elements_across);
    else
      std::snprintf(mesh, sizeof mesh, "%d^2", r.n);
    std::printf("%-22s %-9s %9s %-12s %8.2f %8ld %7ld %5d %6s %9.1e %10.2f %8.3f %-12s%s\n",
                r.scene.c_str(), r.model.c_str(), mesh, r.solver.c_str(), r.report.wall_seconds,
                r.report.iterations, r.report.factorizations, r.increments,
                r.report.converged ? "yes" : "no", r.report.residual_relative, r.form.height * 1e3,
                r.form.total_curvature, r.form.classification.c_str(),
                r.over_budget      ? "  (budget)"
                : !r.error.empty() ? ("  (error: " + r.error + ")").c_str()
                : r.stable         ? ""
                                   : "  (saddle)");
  }
}

// The cost's growth with vertices and the continuum's mesh-convergence checks.
void print_scene_summary(const std::vector<SceneBenchSummary>& summaries) {
  std::printf("\n%-22s %-9s %-12s %s\n", "scene", "model", "solver",
              "wall ~ vertices^p; mesh convergence (max_edge against half)");
  for (const auto& s : summaries) {
    std::printf("%-22s %-9s %-12s ", s.scene.c_str(), s.model.c_str(), s.solver.c_str());
    if (s.runs >= 2)
      std::printf("p = %.2f (%d runs)", s.cost_exponent, s.runs);
    else
      std::printf("p: fewer than two converged runs");
    for (const auto& c : s.checks)
      std::printf("; %.3g mm: %s", c.max_edge * 1e3, c.result.line().c_str());
    std::printf("\n");
  }
}

}  // namespace

int cmd_bench(const BenchArgs& args) {
  BenchOptions o;
  o.sizes = args.sizes;
  o.solvers = args.solvers;
  o.budget = args.budget;
  if (!args.quiet) o.log = [](const std::string& line) { std::cerr << line << "\n"; };
  const std::vector<BenchRow> rows = run_bench(o);
  const std::vector<SceneBenchRow> scene_rows =
      args.scenes ? run_scene_bench(args) : std::vector<SceneBenchRow>{};
  const std::vector<SceneBenchSummary> summaries = summarize_scene_bench(scene_rows);
  if (args.json || !args.json_out.empty()) {
    nlohmann::json j = bench_report(rows, o, omp_get_max_threads());
    if (args.scenes) {
      j["scenes"] = scene_bench_report(scene_rows);
      j["scene_summary"] = scene_summary_report(summaries);
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
  print_table(rows, o);
  if (args.scenes) {
    print_scene_table(scene_rows, args.budget);
    print_scene_summary(summaries);
  }
  return 0;
}

}  // namespace membra::cli
