#include "membra/process/scene_bench.hpp"

#include <cmath>
#include <stdexcept>
#include <variant>

#include "membra/process/run.hpp"

namespace membra {
namespace {

// Thrown from the progress callback to stop a run at its budget.
struct OverBudget : std::runtime_error {
  OverBudget() : std::runtime_error("over budget") {}
};

int path_increments(const Scene& scene) {
  int n = 0;
  for (const ProtocolStep& p : scene.protocol)
    std::visit(
        [&](const auto& s) {
          if constexpr (requires { s.path.increments; }) n += s.path.increments;
        },
        p.step);
  return n;
}

// The sheet's size, and the continuum's mesh as asked for.
void read_sheet(const Sheet& sheet, SceneBenchRow& row) {
  row.vertices = sheet.model.num_particles();
  if (!sheet.continuum()) return;
  row.max_edge = sheet.mesh.spec.max_edge;
  row.elements_across = sheet.mesh.spec.elements_across;
}

}  // namespace

SceneBenchRow bench_scene(Scene scene, Solver solver, double budget) {
  scene.simulation.solver = solver;
  SceneBenchRow row;
  row.scene = scene.name;
  row.model = to_string(scene.model);
  row.n = scene.grid.nx;
  row.solver = std::string(solver_name(solver));
  if (scene.simulation.multilevel > 0)  // "newton/ml32": multilevel down to 32 nodes
    row.solver += "/ml" + std::to_string(scene.simulation.multilevel);
  row.increments = path_increments(scene);
  const Stopwatch clock;
  try {
    if (scene.simulation.self_contact.on && solver != Solver::newton)
      throw std::invalid_argument(
          "self-contact is kept by Newton's line search; this solver would step through it");
    const RunResult r = run_scene(scene, [&](const Progress&) {
      if (clock.seconds() > budget) throw OverBudget();
    });
    row.report = r.solve;
    // A multilevel run's work is every grid's (its `solve` is the finest grid's, the last).
    if (!r.levels.empty()) {
      row.report = {};
      for (const GridLevel& l : r.levels) accumulate(row.report, l.solve);
    }
    row.height = r.shape.height;
    row.total_curvature = r.curvature.total;
    row.stable = r.stability.checked && r.stability.stable;
    read_sheet(r.prepared.membrane.sheet, row);
    row.form = {r.form_global, r.curvature_global.total, r.shape.global_height,
                r.elastic_energy + r.bending_energy + r.gravity_energy + r.support_energy +
                    r.contact_energy};
  } catch (const OverBudget&) {
    row.over_budget = true;
    row.report.converged = false;
  } catch (const std::exception& e) {
    // One scene the model cannot take (a mesh it cannot make) does not end the bench.
    row.error = e.what();
    row.report.converged = false;
  }
  row.report.wall_seconds = clock.seconds();
  // A run stopped by the budget still says how large its sheet was (prepared again, untimed).
  if (row.over_budget) {
    try {
      read_sheet(prepare_scene(scene).membrane.sheet, row);
    } catch (const std::exception&) {  // it was prepared once already: not expected
    }
  }
  return row;
}

namespace {

void summarize_group(const std::vector<const SceneBenchRow*>& group, SceneBenchSummary& out) {
  std::vector<int> vertices;
  std::vector<double> wall;
  for (const SceneBenchRow* r : group) {
    if (!r->report.converged) continue;
    vertices.push_back(r->vertices);
    wall.push_back(r->report.wall_seconds);
    for (const SceneBenchRow* f : group)
      if (r->max_edge > 0.0 && f->report.converged &&
          std::abs(f->max_edge - 0.5 * r->max_edge) <= 1e-6 * r->max_edge)
        out.checks.push_back({r->max_edge, compare_meshes(r->form, f->form)});
  }
  out.runs = static_cast<int>(vertices.size());
  out.cost_exponent = cost_exponent(vertices, wall);
}

}  // namespace

std::vector<SceneBenchSummary> summarize_scene_bench(const std::vector<SceneBenchRow>& rows) {
  std::vector<SceneBenchSummary> out;
  std::vector<bool> done(rows.size(), false);
  for (size_t i = 0; i < rows.size(); ++i) {
    if (done[i]) continue;
    const SceneBenchRow& a = rows[i];
    std::vector<const SceneBenchRow*> group;
    for (size_t k = i; k < rows.size(); ++k)
      if (!done[k] && rows[k].scene == a.scene && rows[k].model == a.model &&
          rows[k].solver == a.solver)
        group.push_back(&rows[k]), done[k] = true;
    SceneBenchSummary s;
    s.scene = a.scene, s.model = a.model, s.solver = a.solver;
    summarize_group(group, s);
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace membra
