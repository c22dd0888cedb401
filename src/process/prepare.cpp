#include "membra/process/prepare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "membra/core/input_error.hpp"
#include "membra/model/benchmark_problem.hpp"
#include "membra/model/continuum_sheet.hpp"
#include "membra/model/mesh_outlines.hpp"
#include "membra/model/pins.hpp"
#include "membra/model/segment_distance.hpp"
#include "membra/process/cut_after_motion.hpp"
#include "membra/process/memory_estimate.hpp"

namespace membra {
namespace {

// P(n): spacing 1 m, k = 1 N/m, unit masses; the force scale k x h = 1 N makes the tolerance
// absolute, as the problem defines it.
PreparedScene prepare_benchmark(const Scene& scene) {
  BenchmarkProblem b = make_benchmark_problem(scene.benchmark_n);
  const GridSheet grid(scene.grid);
  Sheet sheet{grid,
              scene.sheet.material,
              std::move(b.model),
              std::move(b.triangles),
              LatticeStiffness{1.0, 0.5, 0.1},
              scene.sheet,
              {}};
  PreparedScene p{make_membrane(std::move(sheet)), 0, 1.0, std::nullopt};
  p.membrane.state = b.start;
  p.membrane.sheet.model.gravity = Vec3::Zero();
  p.membrane.sheet.model.velocity_damping = scene.simulation.damping;
  return p;
}

// The particles the sheet's outline keeps (none removed for a rectangle).
NodeMask outline_mask(const Scene& scene) {
  if (scene.outline != "disk") return {};
  // The ellipse inscribed in the rectangle, with a hair of slack so nodes on it stay.
  const double a = 0.5 * scene.grid.width, b = 0.5 * scene.grid.height;
  return [a, b](double x, double y) {
    const double u = (x - a) / a, v = (y - b) / b;
    return u * u + v * v <= 1.0 + 1e-9;
  };
}

// The steps the continuum sheet cannot take yet, refused before anything runs.
void check_continuum_protocol(const Scene& scene) {
  for (const ProtocolStep& step : scene.protocol) {
    const auto* grow = step.as<GrowStep>();
    if (grow && grow->grow.family)
      throw InputError(step.pointer + "/family",
                       "a spring family is the lattice's; the continuum sheet grows as a whole "
                       "(leave \"family\" out, or set \"model\": \"lattice\")");
    if (const auto* add = step.as<AddSpringsStep>(); add && add->along_given)
      throw InputError(step.pointer + "/along",
                       "spring families are the lattice's; on the continuum sheet added springs "
                       "lie along the mesh's edges (leave \"along\" out, or set \"model\": "
                       "\"lattice\")");
  }
}

// The mesher's message "sheet.mesh.max_edge: must be positive" as an InputError at
// /sheet/mesh/max_edge; the material's at /sheet/material.
InputError mesh_error(const std::string& what) {
  const size_t colon = what.find(": ");
  const std::string path = colon == std::string::npos ? "" : what.substr(0, colon);
  if (path.rfind("sheet", 0) != 0 || path.find(' ') != std::string::npos)
    return InputError("/sheet/mesh", what);
  std::string pointer = "/" + path;
  std::replace(pointer.begin(), pointer.end(), '.', '/');
  return InputError(pointer, what.substr(colon + 2));
}

Sheet continuum_sheet(const Scene& scene) {
  check_continuum_protocol(scene);
  try {
    return build_continuum_sheet(continuum_spec(scene));
  } catch (const std::invalid_argument& e) {
    throw mesh_error(e.what());
  } catch (const std::runtime_error& e) {  // the mesher's vertex cap
    throw InputError("/sheet/mesh", e.what());
  }
}

// A hole's outline on the natural sheet must keep clear of the sheet's outline: the mesh would
// otherwise meet it at a sliver, and the frame would hold the hole's edge.
void check_hole_inside(const ContinuumSpec& spec, const Polygon2& hole, const std::string& where) {
  const double a = 0.5 * spec.width, b = 0.5 * spec.height, margin = spec.mesh.tolerance;
  for (const Vec2& p : hole) {
    const double u = p.x() - a, v = p.y() - b;
    const bool inside = spec.disk ? (u / (a - margin)) * (u / (a - margin)) +
                                            (v / (b - margin)) * (v / (b - margin)) <
                                        1.0
                                  : std::abs(u) < a - margin && std::abs(v) < b - margin;
    if (inside) continue;
    char at[64];
    std::snprintf(at, sizeof at, "%.1f, %.1f mm", 1e3 * p.x(), 1e3 * p.y());
    throw InputError(where, std::string("the hole reaches the sheet's outline (at ") + at +
                                " on the natural sheet); on the continuum model a hole lies "
                                "inside the sheet");
  }
}

// p moved onto the nearest edge of the closed polygon when within `reach` of it.
Vec2 snapped_to(const Polygon2& poly, double reach, Vec2 p) {
  double best = reach;
  Vec2 out = p;
  for (size_t k = 0; k < poly.size(); ++k) {
    const Vec2 q = nearest_on_segment(p, poly[k], poly[(k + 1) % poly.size()]);
    const double d = (p - q).norm();
    if (d < best) best = d, out = q;
  }
  return out;
}

// A slit on the natural sheet: its line pulled back by the stretch, every point inside the
// sheet or on its outline (where the slit opens the rim; a point within the chord tolerance of
// the meshed outline is moved onto it, so the mesher joins them).
void add_slit(const CutStep& cut, const Vec2& stretch, const std::string& pointer,
              ContinuumSpec& spec) {
  const double a = 0.5 * spec.width, b = 0.5 * spec.height, slack = spec.mesh.tolerance;
  const Polygon2 outline = sheet_outline(spec.width, spec.height, spec.disk, slack);
  Polyline2 line;
  for (const Vec2& q : cut.line) {
    const Vec2 p = snapped_to(outline, 2.0 * slack, q.cwiseQuotient(stretch));
    const double u = p.x() - a, v = p.y() - b;
    const bool inside = spec.disk ? (u / a) * (u / a) + (v / b) * (v / b) <= 1.0 + slack / a
                                  : std::abs(u) <= a + slack && std::abs(v) <= b + slack;
    if (!inside)
      throw InputError(pointer + "/line",
                       "the cut leaves the sheet; on the continuum model a slit lies inside the "
                       "sheet or ends on its outline");
    line.push_back(p);
  }
  spec.slits.push_back(std::move(line));
}

}  // namespace

ContinuumSpec continuum_spec(const Scene& scene) {
  ContinuumSpec spec;
  spec.width = scene.grid.width, spec.height = scene.grid.height;
  spec.disk = scene.outline == "disk";
  spec.mesh = scene.mesh;
  spec.material = scene.sheet.material;
  Vec2 stretch(1.0, 1.0);
  BoundaryOptions o;
  o.tolerance = scene.mesh.tolerance;
  const bool continuum = scene.model == SheetModel::continuum;
  for (size_t k = 0; k < scene.protocol.size(); ++k) {
    const ProtocolStep& step = scene.protocol[k];
    if (const auto* st = step.as<StretchStep>()) stretch = stretch.cwiseProduct(st->lambda);
    const auto* imp = step.as<ImpregnateStep>();
    // A cut drawn after the sheet moved is meshed once the run has pulled it back to the
    // natural sheet (cut_after_motion.hpp); until then the mesh has no part of it.
    const auto* cut = continuum && cut_remeshes(scene, k) ? nullptr : step.as<CutStep>();
    if (cut && continuum && !cut->line.empty()) add_slit(*cut, stretch, step.pointer, spec);
    const bool hole = cut && cut->hole && continuum;
    if (!imp && !hole) continue;
    const Box2 frame{Vec2::Zero(), stretch.cwiseProduct(Vec2(spec.width, spec.height))};
    for (Polygon2 poly : mesh_outlines(imp ? *imp->pattern : *cut->hole, frame, o)) {
      for (Vec2& p : poly) p = p.cwiseQuotient(stretch);
      if (hole) check_hole_inside(spec, poly, step.pointer + "/hole");
      spec.features.push_back(std::move(poly));
    }
  }
  return spec;
}

int pin(const std::vector<PinSpec>& pins, const std::string& where, PreparedScene& p) {
  try {
    return apply_pins(pins, p.membrane.sheet.grid, p.membrane.sheet.model);
  } catch (const std::invalid_argument& e) {
    throw InputError(where, e.what());
  }
}

namespace {

// A table at the frame's height (z = 0) under every particle, when the scene asks for one.
void place_support(const Scene& scene, Model& m) {
  if (scene.simulation.support == Support::table)
    m.table.rest_on(m.mass, scene.simulation.gravity, 0.0, TableContact::kDefaultSoftness);
}

// The continuum sheet: its force scale is the lattice's at the mesh's mean edge.
PreparedScene prepare_continuum(const Scene& scene) {
  PreparedScene p{make_membrane(continuum_sheet(scene)), 0, 0.0, std::nullopt};
  p.pinned = pin(scene.pins, "/pins", p);
  Model& m = p.membrane.sheet.model;
  m.gravity = Vec3(0.0, 0.0, -scene.simulation.gravity);
  m.velocity_damping = scene.simulation.damping;
  place_support(scene, m);
  if (const SelfContactSpec& c = scene.simulation.self_contact; c.on)
    m.self_contact.cover(p.membrane.sheet.triangles, m.reference, c.gap, c.pressure, c.exclusion);
  p.force_scale = p.membrane.sheet.stiffness.stretch * p.membrane.sheet.mesh.mean_edge;
  return p;
}

}  // namespace

PreparedScene prepare_scene(const Scene& scene) {
  // Before allocating anything; the continuum sheet's mesher estimates its own size.
  if (scene.model == SheetModel::lattice) check_memory(scene, machine_memory());
  if (scene.benchmark_n > 0) return prepare_benchmark(scene);
  if (scene.model == SheetModel::continuum && scene.benchmark_n == 0)
    return prepare_continuum(scene);
  PreparedScene p{make_membrane(build_sheet(scene.grid, scene.sheet, outline_mask(scene))), 0, 0.0,
                  std::nullopt};
  p.pinned = pin(scene.pins, "/pins", p);
  Model& m = p.membrane.sheet.model;
  m.gravity = Vec3(0.0, 0.0, -scene.simulation.gravity);
  m.velocity_damping = scene.simulation.damping;
  place_support(scene, m);
  const LatticeStiffness& k = p.membrane.sheet.stiffness;
  p.force_scale = (k.stretch > 0.0 ? k.stretch : k.shear) * p.membrane.sheet.grid.hx();
  return p;
}

}  // namespace membra
