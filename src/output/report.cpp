#include "membra/output/report.hpp"

#include <cmath>
#include <numbers>

#include "membra/core/units.hpp"
#include "membra/version.hpp"

namespace membra {
namespace {

using nlohmann::json;

json mm3(const Vec3& v) {
  return {v.x() / units::mm, v.y() / units::mm, v.z() / units::mm};
}

const double per_m2 = 1.0;  // curvature is reported in 1/m^2, SI's own (docs/outputs.md, "Units")

// What the solves did, the model's size, and the stiffnesses.
// The model, and the continuum sheet's mesh as made and asked for: a script reruns the scene at
// half the element size with --set sheet.mesh.max_edge=...
void report_model(const Scene& scene, const Sheet& sheet, json& j) {
  j["model"] = to_string(scene.model);
  if (!sheet.continuum()) return;
  const SheetMesh& m = sheet.mesh;
  j["mesh"] = {{"vertices", m.vertices},
               {"triangles", m.triangles},
               {"min_angle_deg", m.min_angle_deg},
               {"min_edge_mm", m.min_edge / units::mm},
               {"mean_edge_mm", m.mean_edge / units::mm},
               {"max_edge", m.spec.max_edge / units::mm},
               {"elements_across", m.spec.elements_across},
               {"narrowest_feature_mm", m.narrowest.width / units::mm},
               {"laws", {{"sheet", std::string(to_string(sheet.material.law))}}},
               {"wrinkling", std::string(to_string(sheet.material.wrinkling))}};
}

void report_run(const Scene& scene, const RunResult& r, json& j) {
  const SolveReport& s = r.solve;
  const Model& m = r.prepared.membrane.sheet.model;
  j["membra_version"] = kVersion;
  j["scene"] = scene.name;
  j["solver"] = std::string(solver_name(scene.simulation.solver));
  j["status"] = s.diverged ? "diverged" : (s.converged ? "converged" : "not_converged");
  j["message"] = s.message;
  j["converged"] = s.converged;
  j["residual"] = s.residual;
  j["residual_relative"] = s.residual_relative;
  j["tolerance"] = scene.simulation.tolerance;
  j["iterations"] = s.iterations;
  j["force_passes"] = s.force_passes;
  j["factorizations"] = s.factorizations;
  j["setups"] = s.setups;
  j["negative_curvature_steps"] = s.negative_curvature_steps;
  j["lanczos_steps"] = s.lanczos_steps;
  j["tangent_corrections"] = s.tangent_corrections;
  j["increments"] = s.increments;
  j["increments_halved"] = s.increments_halved;
  j["wall_seconds"] = s.wall_seconds;
  j["max_seconds"] = scene.simulation.max_seconds;
  j["out_of_time"] = r.out_of_time;
  j["warnings"] = r.warnings;
  j["simulated_seconds"] = r.prepared.membrane.state.time;
  j["particles"] = m.num_particles();
  j["springs"] = m.springs.size() + m.added_springs.size();
  j["triangles"] = r.prepared.membrane.sheet.triangles.size();
  j["pinned"] = r.prepared.pinned;
  report_model(scene, r.prepared.membrane.sheet, j);
  j["support"] = to_string(scene.simulation.support);
  if (m.table.size() > 0)
    j["table"] = {{"touching", r.table.touching},
                  {"max_depth_mm", r.table.max_depth / units::mm},
                  {"reaction_N", r.table.reaction},
                  {"weight_N", r.table.weight}};
  if (const SelfContact& c = m.self_contact; c.enabled())
    j["self_contact"] = {{"gap_mm", c.gap / units::mm},
                         {"pressure_kPa", c.pressure / 1e3},
                         {"exclusion_mm", c.exclusion / units::mm},
                         {"touching", r.contact.touching},
                         {"min_distance_mm", r.contact.min_distance / units::mm},
                         {"push_N", r.contact.push}};
  j["stiffness"] = {{"stretch", r.prepared.membrane.sheet.stiffness.stretch / units::N_per_mm},
                    {"shear", r.prepared.membrane.sheet.stiffness.shear / units::N_per_mm},
                    {"flex", r.prepared.membrane.sheet.stiffness.flex / units::N_per_mm}};
}

// What each step did.
void report_steps(const RunResult& r, json& j) {
  j["steps"] = nlohmann::json::array();
  for (const StepReport& step : r.steps) {
    nlohmann::json js = {{"step", step.name},
                         {"iterations", step.solve.iterations},
                         {"residual_relative", step.solve.residual_relative},
                         {"converged", step.solve.converged},
                         {"wall_seconds", step.solve.wall_seconds}};
    if (step.name == "impregnate") {
      js = {{"step", step.name}, {"resin_springs", step.resin_springs}};
      if (r.prepared.membrane.sheet.continuum()) js["partly_covered"] = step.partly_covered;
    }
    if (step.name == "add_springs") js["springs_added"] = step.springs_added;
    if (step.name == "cut") {
      js["springs_cut"] = step.springs_cut;
      js["particles_removed"] = step.particles_removed;
    }
    j["steps"].push_back(js);
  }
}

// A principal radius in mm, signed as its curvature (1/m); null (JSON) where the curvature is
// under 1e-3 1/m (a radius beyond a kilometre: flat that way).
json radius_mm(double k) {
  return std::abs(k) < 1e-3 ? json(nullptr) : json(1.0 / k / units::mm);
}

// Energies, shape, curvature, stress of the end state.
void report_form(const RunResult& r, json& j) {
  j["energy"] =
      r.elastic_energy + r.bending_energy + r.gravity_energy + r.support_energy + r.contact_energy;
  j["energy_parts"] = {{"elastic", r.elastic_energy},      {"bending", r.bending_energy},
                       {"gravity", r.gravity_energy},      {"table", r.support_energy},
                       {"self_contact", r.contact_energy}, {"kinetic", r.kinetic_energy}};
  j["shape"] = {{"height", r.shape.height / units::mm},
                {"z_range", r.shape.z_range / units::mm},
                {"global_height", r.shape.global_height / units::mm},
                {"fold_rms", r.shape.fold_rms / units::mm},
                {"fold_max", r.shape.fold_max / units::mm},
                {"bbox_min", mm3(r.shape.bbox_min)},
                {"bbox_max", mm3(r.shape.bbox_max)},
                {"size", mm3(r.shape.bbox_max - r.shape.bbox_min)},
                {"form", r.form}};
  // The whole form's best-fit quadric (docs/measures.md): a bowl's two radii, however it wrinkles.
  if (r.shape.quadric.valid)
    j["shape"]["quadric"] = {
        {"k1", r.shape.quadric.k1},
        {"k2", r.shape.quadric.k2},
        {"rms", r.shape.quadric.rms / units::mm},
        {"radii_mm", {radius_mm(r.shape.quadric.k1), radius_mm(r.shape.quadric.k2)}},
        {"classification", r.shape.quadric.classification}};
  // Where the outputs' positions come from: R x + t of the simulation's (docs/outputs.md).
  json rotation = json::array();
  for (int i = 0; i < 3; ++i)
    rotation.push_back({r.pose.rotation(i, 0), r.pose.rotation(i, 1), r.pose.rotation(i, 2)});
  j["pose"] = {
      {"posed", r.posed}, {"rotation", rotation}, {"translation", mm3(r.pose.translation)}};
  j["curvature"] = {{"total", r.curvature.total},
                    {"positive", r.curvature.positive},
                    {"negative", r.curvature.negative},
                    {"boundary", r.curvature.boundary},
                    {"min_density", r.curvature.min_density * per_m2},
                    {"max_density", r.curvature.max_density * per_m2},
                    {"classification", r.form}};
  // The global form's curvature (window-averaged, docs/measures.md): a wrinkled bowl is a bowl.
  j["curvature"]["global"] = {{"total", r.curvature_global.total},
                              {"positive", r.curvature_global.positive},
                              {"negative", r.curvature_global.negative},
                              {"classification", r.form_global}};
  j["stress"] = {{"min", r.stress.min_stress / units::MPa},
                 {"max", r.stress.max_stress / units::MPa}};
  j["strain"] = {{"min", r.stress.min_strain}, {"max", r.stress.max_strain}};
  j["force"] = {{"min", r.stress.min_force}, {"max", r.stress.max_force}};
}

void report_curvature_map(const CurvatureMapResult& cm, json& j) {
  j["curvature_map"] = {{"step", cm.step},
                        {"reachable", cm.reached >= 1.0},
                        {"reached", cm.reached},
                        {"message", cm.message},
                        {"correlation", cm.match.correlation},
                        {"rms_error", cm.match.rms_error * per_m2},
                        {"relative_rms_error", cm.match.relative_rms_error},
                        {"mean_target", cm.match.mean_target * per_m2},
                        {"mean_measured", cm.match.mean_measured * per_m2},
                        {"interior_particles", cm.match.interior},
                        {"margin", cm.margin / units::mm}};
}

void report_stability(const StabilityReport& st, json& j) {
  j["stability"] = {{"checked", st.checked},
                    {"stable", st.stable},
                    {"min_eigenvalue", st.min_eigenvalue / units::N_per_mm},
                    {"lower_bound", st.lower_bound / units::N_per_mm},
                    {"shift", st.shift / units::N_per_mm},
                    {"seconds", st.seconds},
                    {"message", st.message}};
}

// Where the form passes through itself (measure/self_intersection.hpp): the crossing triangle
// pairs and their place, in the outputs' frame.
void report_self_intersection(const SelfIntersection& si, json& j) {
  j["self_intersection"] = {
      {"pairs", si.pairs},
      {"triangles", si.triangles.size()},
      {"at_mm", {si.at.x() / units::mm, si.at.y() / units::mm, si.at.z() / units::mm}}};
}

// The stress at each cut and hole.
void report_cuts(const RunResult& r, json& j) {
  j["cuts"] = nlohmann::json::array();
  for (const StressConcentration& c : r.concentrations) {
    nlohmann::json cj = {{"step", c.name},
                         {"kind", c.kind},
                         {"peak_stress", c.peak_stress / units::MPa},
                         {"peak_at", {c.peak_at.x() / units::mm, c.peak_at.y() / units::mm}},
                         {"far_field_stress", c.far_field_stress / units::MPa},
                         {"concentration", c.concentration}};
    if (c.has_edge) {
      cj["edge_stress"] = c.edge_stress / units::MPa;
      cj["edge_concentration"] = c.edge_concentration;
      cj["edge_angle"] = c.edge_angle * 180.0 / std::numbers::pi;
      cj["hole_radius"] = c.hole_radius / units::mm;
    }
    j["cuts"].push_back(cj);
  }
}

// The unit of every number in the report.
// The distinct stable forms of an exploration (simulation.explore), most often found first.
void report_branches(const RunResult& r, json& j) {
  j["explore"] = {
      {"releases", r.explored}, {"unsettled", r.unsettled}, {"distinct_forms", r.branches.size()}};
  j["branches"] = json::array();
  for (size_t b = 0; b < r.branches.size(); ++b) {
    const RunResult& f = r.branches[b].run;
    j["branches"].push_back({{"index", b + 1},
                             {"count", r.branches[b].releases.size()},
                             {"releases", r.branches[b].releases},
                             {"height", f.shape.height / units::mm},
                             {"global_height", f.shape.global_height / units::mm},
                             {"total_K", f.curvature.total},
                             {"total_K_global", f.curvature_global.total},
                             {"classification", f.form_global},
                             {"quadric", f.shape.quadric.classification},
                             {"quadric_k1", f.shape.quadric.k1},
                             {"quadric_k2", f.shape.quadric.k2},
                             {"energy", f.elastic_energy + f.bending_energy + f.gravity_energy +
                                            f.support_energy + f.contact_energy},
                             {"self_intersection_pairs", f.self_intersection.pairs},
                             {"output", "branches/" + std::to_string(b + 1) + "/"}});
  }
}

// The grids of a multilevel run (simulation.multilevel), coarsest first.
void report_levels(const RunResult& r, json& j) {
  j["levels"] = json::array();
  for (const GridLevel& l : r.levels) {
    const bool mesh = l.max_edge > 0.0;
    json level = {{"iterations", l.solve.iterations},
                  {"factorizations", l.solve.factorizations},
                  {"converged", l.solve.converged},
                  {"residual_relative", l.solve.residual_relative},
                  {"wall_seconds", l.solve.wall_seconds},
                  {"start", !l.from_coarser ? "path"
                            : mesh          ? "coarser mesh"
                                            : "coarser grid"}};
    if (mesh) {
      level["max_edge_mm"] = l.max_edge / units::mm;
      level["elements_across"] = l.elements_across;
      level["vertices"] = l.vertices;
    } else {
      level["resolution"] = {l.nx, l.ny};
    }
    j["levels"].push_back(level);
  }
}

// The units of the run and form keys.
json form_units() {
  return {
      {"residual", "N"},
      {"residual_relative", "1 (residual / (k_stretch x grid spacing))"},
      {"wall_seconds", "s"},
      {"max_seconds", "s (simulation.max_seconds, the run's wall-time budget; 0: none)"},
      {"simulated_seconds", "s"},
      {"model", "text (lattice: the paper's springs on a grid; continuum: the latex-resin shell)"},
      {"warnings",
       "text (advice before trusting the form, e.g. a grid too coarse for the pattern)"},
      {"mesh.max_edge", "mm (sheet.mesh.max_edge as made; mesh.elements_across likewise)"},
      {"mesh.min_edge_mm", "mm"},
      {"mesh.mean_edge_mm", "mm"},
      {"mesh.min_angle_deg", "degrees"},
      {"mesh.narrowest_feature_mm", "mm (narrowest resin piece or latex gap, natural sheet)"},
      {"stiffness", "N/mm"},
      {"support", "text (none: the piece floats; table: it rests on a frictionless table)"},
      {"table.touching", "particles (resting on the table)"},
      {"table.max_depth_mm", "mm (the deepest particle's depth in the table's soft contact)"},
      {"table.reaction_N", "N (the table's push; at rest, the piece's weight_N)"},
      {"energy",
       "J (elastic + bending + gravitational potential + the table's contact + self-contact)"},
      {"energy_parts.self_contact",
       "J (the barrier keeping the sheet from passing through itself)"},
      {"self_contact.gap_mm", "mm (the distance from which the barrier pushes)"},
      {"self_contact.pressure_kPa", "kPa (the barrier's pressure scale)"},
      {"self_contact.exclusion_mm", "mm (points this near on the natural sheet never touch)"},
      {"self_contact.touching", "pairs (a point and a triangle nearer than the gap)"},
      {"self_contact.min_distance_mm", "mm (the nearest listed pair; the gap when none)"},
      {"self_contact.push_N", "N (the sum of the barrier's push on the touching points)"},
      {"energy_parts", "J"},
      {"shape.height", "mm (extent normal to the best-fit plane)"},
      {"shape.z_range", "mm"},
      {"shape.global_height", "mm (height of the form averaged over windows 1/8 of the sheet)"},
      {"shape.fold_rms", "mm (rms distance from the window's plane: local folds)"},
      {"shape.fold_max", "mm (largest such distance)"},
      {"shape.quadric.k1",
       "1/m (larger principal curvature of the best-fit quadric; radius 1/k1, in mm as radii_mm)"},
      {"shape.quadric.k2", "1/m (smaller; a bowl has both > 0, a saddle k2 < 0)"},
      {"shape.quadric.radii_mm", "mm (1/k1 and 1/k2, signed; null where flat that way)"},
      {"shape.quadric.rms", "mm (the particles' rms distance from that quadric)"},
      {"shape.quadric.classification",
       "text (flat, cylindrical, synclastic, anticlastic; folded: past what a quadric describes)"},
      {"curvature.total", "rad (sum of interior angle defects = integral of K dA)"},
      {"curvature.positive", "rad"},
      {"curvature.negative", "rad"},
      {"curvature.boundary", "rad (sum of pi - angle sum at boundary vertices)"},
      {"curvature.global.total", "rad (of the window-averaged global form)"},
      {"curvature.global.positive", "rad"},
      {"curvature.global.negative", "rad"},
      {"curvature.min_density", "1/m^2"}};
}

// The units of the stress, cut, stability, self-intersection, map and branch keys.
json mechanics_units() {
  return {
      {"stress.min", "MPa (spring force / (tributary width x sheet thickness); < 0 compression)"},
      {"stress.max", "MPa"},
      {"strain", "1 ((l - l0) / l0 of the springs)"},
      {"force", "N (spring forces, tension positive)"},
      {"cuts.peak_stress",
       "MPa (largest in-plane principal stress of the particles within 1.5 spacings of the cut or "
       "hole)"},
      {"cuts.far_field_stress",
       "MPa (median largest principal stress beyond a quarter of the sheet's side)"},
      {"cuts.concentration", "1 (peak / far field)"},
      {"cuts.edge_stress",
       "MPa (holes: largest principal stress extrapolated to the edge of the equal-area circle "
       "from 3-8 spacings off it, largest over 72 rays)"},
      {"cuts.edge_concentration", "1 (edge_stress / far field)"},
      {"cuts.edge_angle", "degrees from +x, paper: the ray of edge_stress"},
      {"cuts.hole_radius", "mm (the circle with the hole's area)"},
      {"cuts.peak_at", "mm, paper coordinates"},
      {"stability.min_eigenvalue",
       "N/mm (upper bound of the energy Hessian's smallest eigenvalue when unstable, else 0)"},
      {"stability.shift", "N/mm (stable means Hessian + shift I is positive definite)"},
      {"self_intersection.pairs",
       "1 (pairs of triangles sharing no vertex that cross: the form passes through itself)"},
      {"self_intersection.triangles", "1 (how many triangles those pairs involve)"},
      {"self_intersection.at_mm",
       "mm, the centroid of the crossing triangle nearest their mean (final.obj's frame)"},
      {"curvature_map.rms_error",
       "1/m^2 (measured - target Gaussian curvature over the interior particles)"},
      {"curvature_map.mean_target", "1/m^2"},
      {"curvature_map.mean_measured", "1/m^2"},
      {"curvature_map.margin", "mm (the interior lies this far from the edge)"},
      {"curvature_map.reached", "1 (share of the map the computed lengths carry)"},
      {"curvature.max_density", "1/m^2"},
      {"shape.bbox_min", "mm"},
      {"shape.bbox_max", "mm"},
      {"shape.size", "mm (the posed form's overall length along x, width along y, height along z)"},
      {"levels.wall_seconds", "s (the grid's solves)"},
      {"branches.height", "mm (as shape.height, of the branch's form)"},
      {"branches.global_height", "mm"},
      {"branches.total_K", "rad (as curvature.total)"},
      {"branches.total_K_global", "rad (as curvature.global.total)"},
      {"branches.energy", "J (as energy)"},
      {"branches.quadric_k1", "1/m (as shape.quadric.k1)"},
      {"branches.quadric_k2", "1/m (as shape.quadric.k2)"},
      {"branches.releases", "which releases ended in the form (0: the scene's own imperfection)"},
      {"coordinates",
       "mm; when pose.posed, the reading pose: centred in x, y, the lowest point at z = 0, z up; "
       "else the simulation's frame"},
      {"pose.rotation", "1 (3 x 3, rows: the outputs' positions are rotation x + translation)"},
      {"pose.translation", "mm"}};
}

json report_units() {
  json units = form_units();
  units.update(mechanics_units());
  return units;
}

}  // namespace

json make_report(const Scene& scene, const RunResult& r) {
  json j;
  report_run(scene, r, j);
  report_steps(r, j);
  if (!r.levels.empty()) report_levels(r, j);
  if (!r.solve.diverged) {
    report_form(r, j);
    if (r.curvature_map) report_curvature_map(*r.curvature_map, j);
    report_stability(r.stability, j);
    report_self_intersection(r.self_intersection, j);
    report_cuts(r, j);
    if (r.explored > 0) report_branches(r, j);
  }
  j["units"] = report_units();
  return j;
}

}  // namespace membra
