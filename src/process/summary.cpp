#include "membra/process/summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "membra/measure/fitted_curvature.hpp"
#include "membra/measure/global_curvature.hpp"
#include "membra/measure/hole_edge.hpp"
#include "membra/measure/mesh_hole_edge.hpp"
#include "membra/measure/quadric_fit.hpp"
#include "membra/measure/reading_pose.hpp"
#include "membra/measure/self_intersection.hpp"
#include "membra/measure/stress.hpp"
#include "membra/measure/stress_tensor.hpp"
#include "membra/model/forces.hpp"

namespace membra {
namespace {

void summarize_form(RunResult& r) {
  const Membrane& mem = r.prepared.membrane;
  const Model& m = mem.sheet.model;
  const State& s = mem.state;
  r.elastic_energy = elastic_energy(m, s.x);
  // Every set that stores bending energy (bilayer moments included: the plate energy's linear
  // part) is reported as bending.
  r.bending_energy = bending_energy(m, s.x);
  r.gravity_energy = gravity_energy(m, s.x);
  r.support_energy = energy_of_kind(m, s.x, EnergyKind::support);
  r.table = m.table.read(s.x);
  r.contact_energy = energy_of_kind(m, s.x, EnergyKind::contact);
  r.contact = m.self_contact.read(s.x);
  r.kinetic_energy = kinetic_energy(m, s.v);
  r.shape = summarize_shape(s.x, m.reference);
  r.curvature = gaussian_curvature(s.x, mem.sheet.triangles);
  // The grid's alternating valence defects need the filter; an irregular mesh's defects scatter
  // from vertex to vertex, and the fitted surface reads the smooth field.
  if (mem.sheet.continuum())
    smooth_density_on_mesh(s.x, mem.sheet.triangles, r.curvature);
  else
    smooth_density_on_grid(mem.sheet.grid, r.curvature);
  r.form = classify_form(r.curvature);
  r.curvature_global = global_curvature(s.x, m.reference, mem.sheet.triangles);
  if (!r.curvature_global.interior.empty()) r.form_global = classify_form(r.curvature_global);
  r.stress = stress_ranges(m, s.x, mem.sheet.material.thickness);
  r.vertex_stress = vertex_stress(m, s.x, mem.sheet.material.thickness);
  // A small residual does not tell a minimum from a soft saddle.
  r.stability = check_stability(m, s.x, mem.sheet.stiffness.stretch);
  // Neither model has self-contact: a form may settle through itself (docs/measures.md).
  r.self_intersection = self_intersections(s.x, mem.sheet.triangles);
}

// Compared over the interior: a tenth of the sheet's smaller side in from the edge, where the
// edge's own (geodesic) curvature and the smoothing of the measure do not reach.
void summarize_curvature_map(RunResult& r, const std::function<double(const Vec2&)>& field) {
  const Membrane& mem = r.prepared.membrane;
  const Model& m = mem.sheet.model;
  CurvatureMapResult& cm = *r.curvature_map;
  cm.target.resize(static_cast<size_t>(m.num_particles()));
  for (int q = 0; q < m.num_particles(); ++q) cm.target[q] = field(m.reference.col(q).head<2>());
  cm.margin = 0.1 * std::min(mem.sheet.grid.width(), mem.sheet.grid.height());
  cm.match = match_curvature(mem.sheet, cm.target, r.curvature.density, cm.margin);
}

// Peak within 1.5 spacings (the particles on the new edge) against the median far away; for
// holes also the edge value read off the grid's staircase (hole_edge.hpp).
// On the continuum sheet the particles' stress is vertex_stress (the triangles' largest principal
// stress averaged), "near" is within two of the mesh's mean edges, and the hole's edge is
// extrapolated from the triangles (mesh_hole_edge.hpp).
void summarize_features(RunResult& r) {
  const Membrane& mem = r.prepared.membrane;
  const Model& m = mem.sheet.model;
  const GridSheet& g = mem.sheet.grid;
  const bool mesh = mem.sheet.continuum();
  const auto principal =
      mesh ? vertex_stress(m, mem.state.x, mem.sheet.material.thickness)
           : max_principal_stress(node_stress(g, m, mem.state.x, mem.sheet.material.thickness));
  const double near = mesh ? 2.0 * mem.sheet.mesh.mean_edge : 1.5 * std::max(g.hx(), g.hy());
  const double far = 0.25 * std::min(g.width(), g.height());
  for (const StressFeature& f : r.features) {
    StressConcentration c = stress_concentration(m, principal, f, near, far);
    if (f.kind == "hole") {
      const HoleEdge e =
          mesh ? mesh_hole_edge(mem.sheet, mem.state.x, f.where) : hole_edge(g, principal, f.where);
      c.has_edge = e.valid;
      c.edge_stress = e.value;
      c.edge_angle = e.angle;
      c.hole_radius = e.radius;
      if (e.valid && c.far_field_stress > 0.0) c.edge_concentration = e.value / c.far_field_stress;
    }
    r.concentrations.push_back(c);
  }
}

// The final state, its velocities and its frames turned into the reading pose of the quadric
// summarize_form fitted. Of the shape, only what depends on where the form lies changes: its
// box, z range and plane normal, and the quadric's frame. A form still held, by pins or against
// gravity, keeps the frame it hangs in.
void pose_form(RunResult& r) {
  State& s = r.prepared.membrane.state;
  const Model& m = r.prepared.membrane.sheet.model;
  if (m.gravity.squaredNorm() > 0.0) return;
  for (int p = 0; p < m.num_particles(); ++p)
    if (m.pinned(p)) return;
  r.pose = reading_pose(s.x, r.shape.quadric);
  r.posed = true;
  const Eigen::Matrix3d& turn = r.pose.rotation;
  s.x = (turn * s.x).colwise() + r.pose.translation;
  s.v = turn * s.v;
  for (Frame& f : r.frames) f.x = (turn * f.x).colwise() + r.pose.translation;
  ShapeSummary& shape = r.shape;
  shape.bbox_min = s.x.rowwise().minCoeff();
  shape.bbox_max = s.x.rowwise().maxCoeff();
  shape.z_range = shape.bbox_max.z() - shape.bbox_min.z();
  shape.normal = turn * shape.normal;
  if (r.self_intersection.pairs > 0)
    r.self_intersection.at = turn * r.self_intersection.at + r.pose.translation;
  QuadricFit& q = shape.quadric;
  q.centre = turn * q.centre + r.pose.translation;
  for (Vec3* d : {&q.normal, &q.d1, &q.d2, &q.paper_x}) *d = turn * *d;
}

}  // namespace

void summarize_run(RunResult& r, const std::function<double(const Vec2&)>& curvature_field) {
  summarize_form(r);
  if (r.curvature_map) summarize_curvature_map(r, curvature_field);
  if (!r.features.empty()) summarize_features(r);
  pose_form(r);
}

std::string form_line(const RunResult& r) {
  const QuadricFit& q = r.shape.quadric;
  const double mm = 1e-3;
  char buf[200];
  std::snprintf(buf, sizeof buf, "form: %.1f mm high", r.shape.height / mm);
  const std::string line = buf;
  if (!q.valid) return line;
  if (q.classification == "folded")
    return line + ", rolled or folded past what a quadric describes";
  // A radius of a metre or more reads as straight: the classification already says "flat" or
  // "cylindrical" then, and a number in kilometres only distracts.
  auto radius = [&](double k) {  // k in 1/m
    if (!(std::abs(k) > 1.0)) return std::string("straight");
    std::snprintf(buf, sizeof buf, "%.0f mm", 1.0 / k / mm);
    return std::string(buf);
  };
  const std::string r1 = radius(q.k1), r2 = radius(q.k2);
  std::snprintf(buf, sizeof buf, " (the sheet %.1f mm rms off it)", q.rms / mm);
  return line + ", a " + q.classification + " quadric of radii " + r1 + " and " + r2 + buf;
}

}  // namespace membra
