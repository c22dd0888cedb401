#include "membra/io/scene_writer.hpp"

#include <cstdio>
#include <cstdlib>
#include <map>
#include <type_traits>

#include "membra/core/units.hpp"
#include "membra/model/material.hpp"

namespace membra {
namespace {

using nlohmann::json;

// `si` in `unit`s, as the shortest decimal that the reader (value x unit) turns back into `si`
// exactly, so that a written scene reads back to the same typed scene.
double in(double si, double unit) {
  const double v = si / unit;
  for (int digits = 1; digits <= 17; ++digits) {
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    const double candidate = std::strtod(text, nullptr);
    if (candidate * unit == si) return candidate;
  }
  return v;
}

json mm(const Vec2& p) {
  return {in(p.x(), units::mm), in(p.y(), units::mm)};
}

json mm_points(const std::vector<Vec2>& points) {
  json out = json::array();
  for (const Vec2& p : points) out.push_back(mm(p));
  return out;
}

const char* direction_name(GrowDirection d) {
  switch (d) {
    case GrowDirection::all:
      return "all";
    case GrowDirection::x:
      return "x";
    case GrowDirection::y:
      return "y";
    case GrowDirection::radial:
      return "radial";
    case GrowDirection::hoop:
      return "hoop";
  }
  return "all";
}

json write_path(const PathSettings& s, json j) {
  j["increments"] = s.increments;
  j["perturbation"] = in(s.perturbation, units::mm);
  j["seed"] = s.seed;
  return j;
}

json write_pin(const PinSpec& p) {
  switch (p.kind) {
    case PinSpec::Kind::corners:
      return {{"corners", true}};
    case PinSpec::Kind::edge:
      return {{"edge", p.edge}};
    case PinSpec::Kind::point:
      return {{"point", mm(p.point)}};
    case PinSpec::Kind::box:
      return {{"box",
               {in(p.box_min.x(), units::mm), in(p.box_min.y(), units::mm),
                in(p.box_max.x(), units::mm), in(p.box_max.y(), units::mm)}}};
  }
  return json::object();
}

json write_pins(const std::vector<PinSpec>& pins) {
  json out = json::array();
  for (const PinSpec& p : pins) out.push_back(write_pin(p));
  return out;
}

json write_hold(const FrameEdges& h) {
  json edges = json::array();
  for (auto [on, name] : {std::pair{h.left, "left"}, std::pair{h.right, "right"},
                          std::pair{h.bottom, "bottom"}, std::pair{h.top, "top"}})
    if (on) edges.push_back(name);
  return edges;
}

json write_grow(const GrowStep& s) {
  const GrowSpec& g = s.grow;
  json j = {{"step", "grow"},
            {"factor", write_field(s.factor)},
            {"family", g.family ? std::string(to_string(*g.family)) : "all"},
            {"direction", direction_name(g.direction)},
            {"center", mm(g.center)}};
  if (s.region) j["region"] = write_pattern(*s.region);
  return write_path(s.path, j);
}

json write_add_springs(const AddSpringsStep& s) {
  const AddSpringsSpec& a = s.add;
  json j = {{"step", "add_springs"},
            {"pattern", write_pattern(s.region)},
            {"along", a.along ? std::string(to_string(*a.along)) : "any"},
            {"count", a.count},
            {"rest_factor", a.rest_factor}};
  if (a.stiffness > 0.0) j["stiffness"] = in(a.stiffness, units::N_per_mm);
  return write_path(s.path, j);
}

json write_cut(const CutStep& s) {
  json j = {{"step", "cut"}};
  if (!s.line.empty()) j["line"] = mm_points(s.line);
  if (s.hole_spec) j["hole"] = write_pattern(*s.hole_spec);
  return j;
}

// The law only where it matters: the lattice's springs are linear whatever it says.
json write_material(const Material& m, bool with_law) {
  json j = {{"E", in(m.youngs_modulus, units::MPa)},
            {"thickness", in(m.thickness, units::mm)},
            {"density", in(m.density, units::g_per_cm3)}};
  if (with_law) j["law"] = std::string(to_string(m.law));
  if (with_law && m.wrinkling != Wrinkling::full)
    j["wrinkling"] = std::string(to_string(m.wrinkling));
  return j;
}

bool same_material(const Material& a, const Material& b) {
  return a.youngs_modulus == b.youngs_modulus && a.thickness == b.thickness &&
         a.density == b.density && a.law == b.law && a.wrinkling == b.wrinkling;
}

// The materials the scene uses that are not presets as they stand, by name.
json write_materials(const Scene& scene) {
  std::map<std::string, Material> used = {{scene.sheet.material.name, scene.sheet.material}};
  for (const ProtocolStep& s : scene.protocol)
    if (const auto* i = s.as<ImpregnateStep>()) used[i->resin.name] = i->resin;
  json out = json::object();
  for (const auto& [name, m] : used) {
    const auto preset = material_preset(name);
    if (!preset || !same_material(*preset, m))
      out[name] = write_material(m, scene.model == SheetModel::continuum);
  }
  return out;
}

json write_sheet(const Scene& scene) {
  const SheetOptions& o = scene.sheet;
  json j = {{"size", {in(scene.grid.width, units::mm), in(scene.grid.height, units::mm)}},
            {"resolution", {scene.grid.nx, scene.grid.ny}},
            {"material", o.material.name},
            {"bending", o.bending},
            {"outline", scene.outline},
            {"springs",
             {{"stretch", o.stretch},
              {"shear", o.shear},
              {"flex", o.flex},
              {"flex_ratio", o.flex_ratio}}}};
  if (scene.model == SheetModel::continuum)
    j["mesh"] = {{"max_edge", in(scene.mesh.max_edge, units::mm)},
                 {"elements_across", scene.mesh.elements_across},
                 {"min_angle", scene.mesh.min_angle_deg},
                 {"grading", scene.mesh.grading},
                 {"tolerance", in(scene.mesh.tolerance, units::mm)}};
  return j;
}

json write_simulation(const Scene& scene) {
  const SimulationSpec& s = scene.simulation;
  json j = {{"solver", std::string(solver_name(s.solver))},
            {"G", s.gravity},
            {"T", s.dt},
            {"D", s.damping},
            {"spring_damping", in(scene.sheet.spring_damping, units::N_per_mm)},
            {"steps", s.steps},
            {"max_iterations", s.max_iterations},
            {"tolerance", s.tolerance},
            {"path_tolerance", s.path_tolerance},
            {"stop_when_converged", s.stop_when_converged},
            {"tangent_correction", s.tangent_correction},
            {"support", to_string(s.support)},
            {"multilevel", s.multilevel}};
  if (s.ramp_seconds > 0.0) j["ramp_seconds"] = s.ramp_seconds;
  if (s.self_contact.on)
    j["self_contact"] = {{"gap", in(s.self_contact.gap, units::mm)},
                         {"pressure", s.self_contact.pressure / 1e3},
                         {"exclusion", in(s.self_contact.exclusion, units::mm)}};
  if (scene.sheet.stretch_stiffness) j["K"] = in(*scene.sheet.stretch_stiffness, units::N_per_mm);
  return j;
}

json write_output(const OutputSpec& o) {
  return {{"frames", o.frames},
          {"camera", {{"azimuth", o.azimuth}, {"elevation", o.elevation}}},
          {"image_size", {o.image_width, o.image_height}},
          {"colormap", to_string(o.colormap)}};
}

}  // namespace

json write_pattern(const PatternSpec& s) {
  switch (s.kind) {
    case PatternSpec::Kind::strip:
      return {{"strip", {{"points", mm_points(s.points)}, {"width", in(s.width, units::mm)}}}};
    case PatternSpec::Kind::ellipse: {
      json e = {{"center", mm(s.center)}, {"radii", mm(s.radii)}, {"angle", s.angle_degrees}};
      if (s.ring_width) e["ring_width"] = in(*s.ring_width, units::mm);
      return {{"ellipse", e}};
    }
    case PatternSpec::Kind::circle:
      return {{"circle", {{"center", mm(s.center)}, {"radius", in(s.radius, units::mm)}}}};
    case PatternSpec::Kind::hyperbola:
      return {{"hyperbola",
               {{"center", mm(s.center)},
                {"a", in(s.a, units::mm)},
                {"b", in(s.b, units::mm)},
                {"angle", s.angle_degrees},
                {"width", in(s.width, units::mm)},
                {"opens", s.opens}}}};
    case PatternSpec::Kind::polygon:
      return {{"polygon", {{"points", mm_points(s.points)}}}};
    case PatternSpec::Kind::image: {
      json i = {{"file", s.file}, {"threshold", s.threshold}, {"invert", s.invert}};
      if (s.origin) i["origin"] = mm(*s.origin);
      if (s.size) i["size"] = mm(*s.size);
      return {{"image", i}};
    }
    case PatternSpec::Kind::union_of:
    case PatternSpec::Kind::difference: {
      json parts = json::array();
      for (const PatternSpec& p : s.parts) parts.push_back(write_pattern(p));
      return {{s.kind == PatternSpec::Kind::union_of ? "union" : "difference", parts}};
    }
  }
  return json::object();
}

json write_field(const FieldSpec& s) {
  switch (s.kind) {
    case FieldSpec::Kind::constant:
      return s.value;
    case FieldSpec::Kind::formula:
      return s.formula;
    case FieldSpec::Kind::preset:
      return {{"preset", s.preset}, {"amplitude", s.amplitude}};
    case FieldSpec::Kind::image: {
      json j = {{"image", s.file}, {"range", {s.range.x(), s.range.y()}}};
      if (s.origin) j["origin"] = mm(*s.origin);
      if (s.size) j["size"] = mm(*s.size);
      return j;
    }
  }
  return nullptr;
}

json write_step(const ProtocolStep& step) {
  return std::visit(
      [](const auto& s) -> json {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, StretchStep>)
          return {{"step", "stretch"},
                  {"lambda", {s.lambda.x(), s.lambda.y()}},
                  {"hold", write_hold(s.hold)}};
        if constexpr (std::is_same_v<T, ImpregnateStep>)
          return {{"step", "impregnate"},
                  {"pattern", write_pattern(s.pattern_spec)},
                  {"material", s.resin.name},
                  {"resin_side", s.resin_side > 0 ? "top" : "bottom"},
                  {"bilayer", s.bilayer}};
        if constexpr (std::is_same_v<T, ReleaseStep>)
          return write_path(s.path, {{"step", "release"}});
        if constexpr (std::is_same_v<T, LoadStep>) {
          json j = {{"step", "load"}, {"pins", write_pins(s.pins)}};
          if (s.gravity) j["gravity"] = *s.gravity;
          return j;
        }
        if constexpr (std::is_same_v<T, GrowStep>) return write_grow(s);
        if constexpr (std::is_same_v<T, AddSpringsStep>) return write_add_springs(s);
        if constexpr (std::is_same_v<T, CutStep>) return write_cut(s);
        if constexpr (std::is_same_v<T, CurvatureMapStep>)
          return write_path(s.path, {{"step", "curvature_map"}, {"K", write_field(s.field)}});
      },
      step.step);
}

json write_scene(const Scene& scene) {
  json j = {{"name", scene.name}, {"description", scene.description}};
  if (scene.model == SheetModel::continuum) j["model"] = "continuum";
  if (scene.benchmark_n > 0) {
    j["benchmark"] = {{"problem", "P"}, {"n", scene.benchmark_n}};
  } else {
    const json materials = write_materials(scene);
    if (!materials.empty()) j["materials"] = materials;
    j["sheet"] = write_sheet(scene);
    j["pins"] = write_pins(scene.pins);
    json protocol = json::array();
    for (const ProtocolStep& s : scene.protocol) protocol.push_back(write_step(s));
    j["protocol"] = protocol;
  }
  j["simulation"] = write_simulation(scene);
  j["output"] = write_output(scene.output);
  return j;
}

}  // namespace membra
