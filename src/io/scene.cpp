#include "membra/io/scene.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "membra/core/units.hpp"
#include "membra/io/field_reader.hpp"
#include "membra/io/json_reader.hpp"
#include "membra/io/pattern_reader.hpp"

namespace membra {
namespace {

using nlohmann::json;

// Known keys, one list per object; scene_known_keys() exposes them for the schema test.
const std::vector<std::string_view> kBenchmarkKeys = {"problem", "n"};
const std::vector<std::string_view> kTopKeys = {"benchmark", "$schema",   "name", "description",
                                                "sheet",     "materials", "pins", "simulation",
                                                "protocol",  "output"};
const std::vector<std::string_view> kOutputKeys = {"frames", "camera", "image_size"};
const std::vector<std::string_view> kCameraKeys = {"azimuth", "elevation"};
const std::vector<std::string_view> kSheetKeys = {"size",    "resolution", "material",
                                                  "springs", "bending",    "outline"};
const std::vector<std::string_view> kStretchKeys = {"step", "lambda", "hold"};
const std::vector<std::string_view> kImpregnateKeys = {"step", "pattern", "material", "resin_side",
                                                       "bilayer"};
const std::vector<std::string_view> kReleaseKeys = {"step", "increments", "perturbation", "seed"};
const std::vector<std::string_view> kLoadKeys = {"step", "gravity", "pins"};
const std::vector<std::string_view> kGrowKeys = {"step",       "factor",       "family",
                                                 "direction",  "center",       "region",
                                                 "increments", "perturbation", "seed"};
const std::vector<std::string_view> kAddSpringsKeys = {"step",       "pattern",      "along",
                                                       "count",      "stiffness",    "rest_factor",
                                                       "increments", "perturbation", "seed"};
const std::vector<std::string_view> kCutKeys = {"step", "line", "hole"};
const std::vector<std::string_view> kCurvatureMapKeys = {"step", "K", "increments", "perturbation",
                                                         "seed"};
const std::vector<std::string_view> kSpringKeys = {"stretch", "shear", "flex", "flex_ratio"};
const std::vector<std::string_view> kMaterialKeys = {"preset", "E", "thickness", "density"};
const std::vector<std::string_view> kPinKeys = {"corners", "edge", "point", "box"};
const std::vector<std::string_view> kSimulationKeys = {"solver",
                                                       "K",
                                                       "G",
                                                       "T",
                                                       "D",
                                                       "spring_damping",
                                                       "steps",
                                                       "max_iterations",
                                                       "tolerance",
                                                       "stop_when_converged",
                                                       "path_tolerance"};

// Largest grid we accept; the robustness issue adds a memory-based limit.
constexpr long kMaxNodesPerSide = 4096;

std::map<std::string, Material> parse_materials(const json& j) {
  std::map<std::string, Material> out;
  for (const char* name : {"latex", "epoxy"}) out[name] = *material_preset(name);
  if (!j.contains("materials")) return out;
  const auto& mats = j.at("materials");
  if (!mats.is_object())
    throw InputError("/materials",
                     "expected an object of named materials, got " + json_type_name(mats));
  for (const auto& [name, value] : mats.items()) {
    const std::string ptr = "/materials/" + name;
    JsonObject m(value, ptr, kMaterialKeys);
    Material base;
    base.name = name;
    if (m.has("preset")) {
      const std::string preset = m.string("preset", std::nullopt, {"latex", "epoxy"});
      base = *material_preset(preset);
      base.name = name;
    } else if (auto known = material_preset(name)) {
      base = *known;
    }
    const bool complete = base.youngs_modulus > 0.0;
    auto value_or_required = [&](std::string_view key, double current, double scale) {
      return m.number(key, complete ? std::optional<double>(current / scale) : std::nullopt,
                      Bounds::positive()) *
             scale;
    };
    base.youngs_modulus = value_or_required("E", base.youngs_modulus, units::MPa);
    base.thickness = value_or_required("thickness", base.thickness, units::mm);
    base.density = value_or_required("density", base.density, units::g_per_cm3);
    out[name] = base;
  }
  return out;
}

void parse_sheet(const JsonObject& top, const std::map<std::string, Material>& materials,
                 Scene& scene) {
  const JsonObject sheet = top.object("sheet", kSheetKeys);
  const auto size = sheet.numbers("size", 2, Bounds::positive());
  scene.grid.width = size[0] * units::mm;
  scene.grid.height = size[1] * units::mm;
  const auto& res = sheet.at("resolution");
  if (!res.is_array() || res.size() != 2)
    throw InputError(sheet.pointer("resolution"),
                     "expected [nx, ny], the number of particles along x and y");
  for (int k = 0; k < 2; ++k) {
    const std::string ptr = sheet.pointer("resolution") + "/" + std::to_string(k);
    const auto& v = res[static_cast<size_t>(k)];
    if (!v.is_number_integer())
      throw InputError(ptr, "expected an integer number of particles, got " + v.dump());
    const long n = v.get<long>();
    if (n < 2 || n > kMaxNodesPerSide)
      throw InputError(ptr, "must be in [2, " + std::to_string(kMaxNodesPerSide) + "], got " +
                                std::to_string(n));
    (k == 0 ? scene.grid.nx : scene.grid.ny) = static_cast<int>(n);
  }
  // The homogenization (docs/model.md, "Homogenization") is for square cells.
  const double hx = size[0] / (scene.grid.nx - 1), hy = size[1] / (scene.grid.ny - 1);
  if (std::abs(hx / hy - 1.0) > 0.01) {
    std::ostringstream msg;
    msg << "cells must be square for the lattice to be isotropic, but the spacing is " << hx
        << " mm along x and " << hy << " mm along y; choose (nx-1)/(ny-1) = width/height";
    throw InputError(sheet.pointer("resolution"), msg.str());
  }
  const std::string mat = sheet.string("material", "latex");
  const auto it = materials.find(mat);
  if (it == materials.end())
    throw InputError(sheet.pointer("material"), "unknown material '" + mat +
                                                    "': define it under /materials or use a preset "
                                                    "(latex, epoxy)");
  scene.sheet.material = it->second;
  scene.sheet.bending = sheet.boolean("bending", true);
  scene.outline = sheet.string("outline", "rectangle", {"rectangle", "disk"});
  if (sheet.has("springs")) {
    const JsonObject springs = sheet.object("springs", kSpringKeys);
    scene.sheet.stretch = springs.boolean("stretch", true);
    scene.sheet.shear = springs.boolean("shear", true);
    scene.sheet.flex = springs.boolean("flex", false);
    scene.sheet.flex_ratio = springs.number("flex_ratio", 0.1, Bounds::between(0.0, 10.0));
    if (!scene.sheet.stretch && !scene.sheet.shear && !scene.sheet.flex)
      throw InputError(sheet.pointer("springs"), "at least one spring family must be on");
  }
}

void parse_pins(const JsonObject& parent, const Scene& scene, std::vector<PinSpec>& pins) {
  if (!parent.has("pins")) return;
  const auto& arr = parent.at("pins");
  const std::string base = parent.pointer("pins");
  if (!arr.is_array()) throw InputError(base, "expected an array, got " + json_type_name(arr));
  const Bounds in_x = Bounds::between(0.0, scene.grid.width / units::mm);
  const Bounds in_y = Bounds::between(0.0, scene.grid.height / units::mm);
  for (size_t i = 0; i < arr.size(); ++i) {
    const JsonObject p(arr[i], base + "/" + std::to_string(i), kPinKeys);
    int given = 0;
    for (auto k : kPinKeys) given += p.has(k) ? 1 : 0;
    if (given != 1) throw InputError(p.pointer(), "give exactly one of corners, edge, point, box");
    PinSpec pin;
    if (p.has("corners")) {
      if (!p.boolean("corners", std::nullopt)) continue;
      pin.kind = PinSpec::Kind::corners;
    } else if (p.has("edge")) {
      pin.kind = PinSpec::Kind::edge;
      pin.edge = p.string("edge", std::nullopt, {"left", "right", "bottom", "top"});
    } else if (p.has("point")) {
      pin.kind = PinSpec::Kind::point;
      const auto& v = p.at("point");
      if (!v.is_array() || v.size() != 2)
        throw InputError(p.pointer("point"), "expected [x, y] in mm");
      pin.point = {checked_number(v[0], p.pointer("point") + "/0", in_x) * units::mm,
                   checked_number(v[1], p.pointer("point") + "/1", in_y) * units::mm};
    } else {
      pin.kind = PinSpec::Kind::box;
      const auto b = p.numbers("box", 4);
      for (int k = 0; k < 4; ++k)
        checked_number(p.at("box")[static_cast<size_t>(k)],
                       p.pointer("box") + "/" + std::to_string(k), k % 2 == 0 ? in_x : in_y);
      if (!(b[2] >= b[0] && b[3] >= b[1]))
        throw InputError(p.pointer("box"), "expected [x0, y0, x1, y1] with x1 >= x0, y1 >= y0");
      pin.box_min = Vec2(b[0], b[1]) * units::mm;
      pin.box_max = Vec2(b[2], b[3]) * units::mm;
    }
    pins.push_back(pin);
  }
}

void parse_simulation(const JsonObject& top, Scene& scene) {
  SimulationSpec& sim = scene.simulation;
  if (!top.has("simulation")) return;
  const JsonObject s = top.object("simulation", kSimulationKeys);
  const std::string solver =
      s.string("solver", std::string(solver_name(sim.solver)), solver_names());
  sim.solver = *solver_from_name(solver);
  if (s.has("K"))
    scene.sheet.stretch_stiffness =
        s.number("K", std::nullopt, Bounds::positive()) * units::N_per_mm;
  sim.gravity = s.number("G", sim.gravity, Bounds::between(-1e4, 1e4));
  sim.dt = s.number("T", sim.dt, Bounds{0.0, 1.0, true});
  sim.damping = s.number("D", sim.damping, Bounds::non_negative());
  scene.sheet.spring_damping =
      s.number("spring_damping", 0.0, Bounds::non_negative()) * units::N_per_mm;
  sim.steps = s.integer("steps", sim.steps, 0, 1'000'000'000L);
  sim.max_iterations = s.integer("max_iterations", sim.max_iterations, 0, 1'000'000'000L);
  sim.tolerance = s.number("tolerance", sim.tolerance, Bounds{0.0, 1.0, true});
  sim.path_tolerance =
      std::max(sim.tolerance, s.number("path_tolerance", sim.tolerance, Bounds{0.0, 1.0, true}));
  sim.stop_when_converged = s.boolean("stop_when_converged", sim.stop_when_converged);
}

// increments, perturbation and seed: how a step that changes the sheet's shape is followed.
void parse_path(const JsonObject& o, ProtocolStep& step) {
  step.increments = static_cast<int>(o.integer("increments", step.increments, 1, 100000));
  step.perturbation =
      o.number("perturbation", step.perturbation / units::mm, Bounds::non_negative()) * units::mm;
  step.seed = static_cast<std::uint64_t>(o.integer("seed", 1, 0, 2'000'000'000L));
}

SpringFamily spring_family(const std::string& name) {
  if (name == "stretch") return SpringFamily::stretch;
  if (name == "shear") return SpringFamily::shear;
  if (name == "flex") return SpringFamily::flex;
  return SpringFamily::added;
}

std::vector<Vec2> read_polyline(const JsonObject& o, std::string_view key) {
  const auto& arr = o.at(key);
  if (!arr.is_array() || arr.size() < 2)
    throw InputError(o.pointer(key), "expected an array of at least 2 [x, y] points (mm)");
  std::vector<Vec2> pts;
  for (size_t i = 0; i < arr.size(); ++i) {
    const std::string ptr = o.pointer(key) + "/" + std::to_string(i);
    if (!arr[i].is_array() || arr[i].size() != 2) throw InputError(ptr, "expected [x, y] in mm");
    pts.emplace_back(checked_number(arr[i][0], ptr + "/0", {}) * units::mm,
                     checked_number(arr[i][1], ptr + "/1", {}) * units::mm);
  }
  for (size_t i = 0; i + 1 < pts.size(); ++i)
    if ((pts[i + 1] - pts[i]).norm() == 0.0)
      throw InputError(o.pointer(key) + "/" + std::to_string(i + 1),
                       "repeats the point before it (a cut segment needs a length)");
  return pts;
}

// grow: the factor field over paper coordinates, checked positive at every spring midpoint of
// the grid (the points where it will be evaluated) so a bad formula fails before any solve.
void parse_grow(const JsonObject& o, const std::filesystem::path& base_dir, const Scene& scene,
                ProtocolStep& step) {
  step.kind = ProtocolStep::Kind::grow;
  const Vec2 size(scene.grid.width, scene.grid.height);
  FormulaContext ctx;
  ctx.size = size;
  ctx.center = 0.5 * size;
  if (o.has("center")) {
    const auto c = o.numbers("center", 2);
    ctx.center = Vec2(c[0], c[1]) * units::mm;
  }
  GrowSpec& g = step.grow;
  g.center = ctx.center;
  step.grow_factor = read_field_spec(o.at("factor"), o.pointer("factor"), base_dir);
  g.factor = build_field(step.grow_factor, o.pointer("factor"), ctx);
  const int nx = 2 * scene.grid.nx - 1, ny = 2 * scene.grid.ny - 1;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Vec2 p(size.x() * i / (nx - 1), size.y() * j / (ny - 1));
      double f = 0.0;
      try {
        f = g.factor(p);
      } catch (const std::invalid_argument& e) {
        throw InputError(o.pointer("factor"), e.what());
      }
      if (!std::isfinite(f) || !(f > 0.0)) {
        std::ostringstream msg;
        msg << "the growth factor is " << f << " at (" << p.x() / units::mm << ", "
            << p.y() / units::mm << ") mm (paper coordinates); it must be positive everywhere";
        throw InputError(o.pointer("factor"), msg.str());
      }
    }
  const std::string family =
      o.string("family", "all", {"all", "stretch", "shear", "flex", "added"});
  if (family != "all") g.family = spring_family(family);
  const std::string dir = o.string("direction", "all", {"all", "x", "y", "radial", "hoop"});
  g.direction = dir == "x"        ? GrowDirection::x
                : dir == "y"      ? GrowDirection::y
                : dir == "radial" ? GrowDirection::radial
                : dir == "hoop"   ? GrowDirection::hoop
                                  : GrowDirection::all;
  if (o.has("region")) {
    step.grow_region = read_pattern_spec(o.at("region"), o.pointer("region"), base_dir);
    g.region = make_pattern(*step.grow_region, size);
  }
  parse_path(o, step);
}

// The steps, checked in order: the frame size a pattern must fit depends on the stretches
// before it, and a static solve of a free sheet under gravity has no equilibrium.
void parse_protocol(const JsonObject& top, const std::map<std::string, Material>& materials,
                    const std::filesystem::path& base_dir, Scene& scene) {
  if (!top.has("protocol")) return;
  const auto& arr = top.at("protocol");
  if (!arr.is_array()) throw InputError("/protocol", "expected an array of steps");
  Vec2 stretch(1.0, 1.0);
  bool pinned = !scene.pins.empty(), framed = false;
  double gravity = scene.simulation.gravity;
  auto check_equilibrium = [&](const std::string& ptr) {
    if (scene.simulation.is_static() && !pinned && !framed && gravity != 0.0)
      throw InputError(ptr,
                       "a free sheet under gravity has no static equilibrium: pin it (a load "
                       "step with pins) or set simulation.G (or the load step's gravity) to 0");
  };
  for (size_t i = 0; i < arr.size(); ++i) {
    const std::string ptr = "/protocol/" + std::to_string(i);
    if (!arr[i].is_object() || !arr[i].contains("step"))
      throw InputError(
          ptr,
          "expected an object with a \"step\" key (stretch, impregnate, release, load, grow, "
          "add_springs, cut, curvature_map)");
    // Any step's key passes here; each kind then checks its own.
    std::vector<std::string_view> all_keys;
    for (const auto* keys : {&kStretchKeys, &kImpregnateKeys, &kReleaseKeys, &kLoadKeys, &kGrowKeys,
                             &kAddSpringsKeys, &kCutKeys, &kCurvatureMapKeys})
      all_keys.insert(all_keys.end(), keys->begin(), keys->end());
    std::sort(all_keys.begin(), all_keys.end());
    all_keys.erase(std::unique(all_keys.begin(), all_keys.end()), all_keys.end());
    const JsonObject head(arr[i], ptr, all_keys);
    const std::string kind = head.string("step", std::nullopt,
                                         {"stretch", "impregnate", "release", "load", "grow",
                                          "add_springs", "cut", "curvature_map"});
    ProtocolStep step;
    step.pointer = ptr;
    if (kind == "stretch") {
      const JsonObject o(arr[i], ptr, kStretchKeys);
      step.kind = ProtocolStep::Kind::stretch;
      const auto l = o.numbers("lambda", 2, Bounds{0.0, 10.0, true});
      step.lambda = Vec2(l[0], l[1]);
      if (o.has("hold")) {
        const auto& h = o.at("hold");
        if (!h.is_array() || h.empty())
          throw InputError(o.pointer("hold"),
                           "expected a non-empty array of edges: left, right, bottom, top");
        step.hold = {false, false, false, false};
        for (size_t e = 0; e < h.size(); ++e) {
          const std::string ep = o.pointer("hold") + "/" + std::to_string(e);
          const std::string edge = h[e].is_string() ? h[e].get<std::string>() : "";
          if (edge == "left")
            step.hold.left = true;
          else if (edge == "right")
            step.hold.right = true;
          else if (edge == "bottom")
            step.hold.bottom = true;
          else if (edge == "top")
            step.hold.top = true;
          else
            throw InputError(ep, "expected one of left, right, bottom, top, got " + h[e].dump());
        }
      }
      stretch = stretch.cwiseProduct(step.lambda);
      framed = true;
    } else if (kind == "impregnate") {
      const JsonObject o(arr[i], ptr, kImpregnateKeys);
      step.kind = ProtocolStep::Kind::impregnate;
      const Vec2 frame(stretch.x() * scene.grid.width, stretch.y() * scene.grid.height);
      step.pattern_spec = read_pattern_spec(o.at("pattern"), o.pointer("pattern"), base_dir);
      step.pattern = make_pattern(step.pattern_spec, frame);
      const Box2 inside = step.pattern->bounds().intersect({Vec2::Zero(), frame});
      if (inside.empty() || inside.max.x() <= inside.min.x() || inside.max.y() <= inside.min.y()) {
        std::ostringstream msg;
        msg << "the pattern lies outside the frame [0, " << frame.x() / units::mm << "] x [0, "
            << frame.y() / units::mm << "] mm (frame coordinates: the stretched sheet)";
        throw InputError(o.pointer("pattern"), msg.str());
      }
      const std::string mat = o.string("material", "epoxy");
      const auto it = materials.find(mat);
      if (it == materials.end())
        throw InputError(o.pointer("material"), "unknown material '" + mat + "'");
      step.resin = it->second;
      step.resin_side = o.string("resin_side", "top", {"top", "bottom"}) == "top" ? 1 : -1;
      step.bilayer = o.boolean("bilayer", false);
      // The hinges carry only the linear part of the plate energy; the bending elements the
      // quadratic one that stops the curl.
      if (step.bilayer && !scene.sheet.bending)
        throw InputError(o.pointer("bilayer"),
                         "a bilayer needs the sheet's bending (sheet.bending is false)");
    } else if (kind == "release") {
      const JsonObject o(arr[i], ptr, kReleaseKeys);
      step.kind = ProtocolStep::Kind::release;
      parse_path(o, step);
      if (!framed) throw InputError(ptr, "release needs a stretch step before it");
      framed = false;
      check_equilibrium(ptr);
    } else if (kind == "grow") {
      parse_grow(JsonObject(arr[i], ptr, kGrowKeys), base_dir, scene, step);
      check_equilibrium(ptr);
    } else if (kind == "curvature_map") {
      const JsonObject o(arr[i], ptr, kCurvatureMapKeys);
      step.kind = ProtocolStep::Kind::curvature_map;
      FormulaContext ctx;
      ctx.size = Vec2(scene.grid.width, scene.grid.height);
      ctx.center = 0.5 * ctx.size;
      step.curvature_spec = read_field_spec(o.at("K"), o.pointer("K"), base_dir);
      const ScalarField per_mm2 = build_field(step.curvature_spec, o.pointer("K"), ctx);
      step.curvature = [per_mm2](const Vec2& p) { return per_mm2(p) / (units::mm * units::mm); };
      for (int jj = 0; jj < scene.grid.ny; ++jj)
        for (int ii = 0; ii < scene.grid.nx; ++ii) {
          const Vec2 q(scene.grid.width * ii / (scene.grid.nx - 1),
                       scene.grid.height * jj / (scene.grid.ny - 1));
          double k = 0.0;
          try {
            k = per_mm2(q);
          } catch (const std::invalid_argument& e) {
            throw InputError(o.pointer("K"), e.what());
          }
          if (!std::isfinite(k)) {
            std::ostringstream msg;
            msg << "K is " << k << " at (" << q.x() / units::mm << ", " << q.y() / units::mm
                << ") mm; it must be a finite number (1/mm^2) everywhere";
            throw InputError(o.pointer("K"), msg.str());
          }
        }
      parse_path(o, step);
      check_equilibrium(ptr);
    } else if (kind == "add_springs") {
      const JsonObject o(arr[i], ptr, kAddSpringsKeys);
      step.kind = ProtocolStep::Kind::add_springs;
      const Vec2 frame(stretch.x() * scene.grid.width, stretch.y() * scene.grid.height);
      step.add_region = read_pattern_spec(o.at("pattern"), o.pointer("pattern"), base_dir);
      step.add.region = make_pattern(step.add_region, frame);
      const std::string along = o.string("along", "stretch", {"stretch", "shear", "flex", "any"});
      step.add.along = along == "any" ? std::optional<SpringFamily>() : spring_family(along);
      step.add.count = static_cast<int>(o.integer("count", 1, 1, 1000));
      step.add.stiffness =
          o.has("stiffness")
              ? o.number("stiffness", std::nullopt, Bounds::positive()) * units::N_per_mm
              : 0.0;
      step.add.rest_factor = o.number("rest_factor", 1.0, Bounds{0.0, 10.0, true});
      parse_path(o, step);
      check_equilibrium(ptr);
    } else if (kind == "cut") {
      const JsonObject o(arr[i], ptr, kCutKeys);
      step.kind = ProtocolStep::Kind::cut;
      if (!o.has("line") && !o.has("hole"))
        throw InputError(ptr, "a cut needs a \"line\" (polyline, mm) or a \"hole\" (pattern)");
      // Where the sheet is now: the stretched frame, or the natural sheet when no frame holds it.
      const Vec2 frame = framed
                             ? Vec2(stretch.x() * scene.grid.width, stretch.y() * scene.grid.height)
                             : Vec2(scene.grid.width, scene.grid.height);
      const Box2 sheet_box{Vec2::Zero(), frame};
      auto outside = [&](const Box2& b) {
        const Box2 in = b.intersect(sheet_box);
        return in.empty();
      };
      std::ostringstream where;
      where << "[0, " << frame.x() / units::mm << "] x [0, " << frame.y() / units::mm << "] mm";
      if (o.has("line")) {
        step.cut_line = read_polyline(o, "line");
        Box2 b;
        for (const Vec2& q : step.cut_line) b.extend(q);
        if (outside(b))
          throw InputError(o.pointer("line"), "the cut lies outside the sheet " + where.str());
      }
      if (o.has("hole")) {
        step.hole_spec = read_pattern_spec(o.at("hole"), o.pointer("hole"), base_dir);
        step.hole = make_pattern(*step.hole_spec, frame);
        if (outside(step.hole->bounds()))
          throw InputError(o.pointer("hole"), "the hole lies outside the sheet " + where.str());
      }
    } else {
      const JsonObject o(arr[i], ptr, kLoadKeys);
      step.kind = ProtocolStep::Kind::load;
      if (o.has("gravity"))
        step.gravity = o.number("gravity", std::nullopt, Bounds::between(-1e4, 1e4));
      if (step.gravity) gravity = *step.gravity;
      parse_pins(o, scene, step.pins);
      pinned = pinned || !step.pins.empty();
      check_equilibrium(ptr);
    }
    scene.protocol.push_back(std::move(step));
  }
}

}  // namespace

void parse_output(const JsonObject& top, OutputSpec& out) {
  if (!top.has("output")) return;
  const JsonObject o = top.object("output", kOutputKeys);
  out.frames = static_cast<int>(o.integer("frames", 0, 0, 1000));
  if (o.has("camera")) {
    const JsonObject c = o.object("camera", kCameraKeys);
    out.azimuth = c.number("azimuth", out.azimuth, Bounds::between(-360, 360));
    out.elevation = c.number("elevation", out.elevation, Bounds::between(-90, 90));
  }
  if (o.has("image_size")) {
    const auto size = o.numbers("image_size", 2, Bounds::between(64, 8192));
    out.image_width = static_cast<int>(size[0]);
    out.image_height = static_cast<int>(size[1]);
  }
}

Scene parse_scene(const json& j, const std::filesystem::path& base_dir) {
  Scene scene;
  const JsonObject top(j, "", kTopKeys);
  scene.name = top.string("name", "untitled");
  scene.description = top.string("description", "");
  const auto materials = parse_materials(j);
  if (top.has("benchmark")) {
    // The benchmark problem builds its own sheet; it is solved once, as it is.
    const JsonObject b = top.object("benchmark", kBenchmarkKeys);
    b.string("problem", "P", {"P"});
    scene.benchmark_n = static_cast<int>(b.integer("n", std::nullopt, 3, kMaxNodesPerSide));
    for (const char* key : {"sheet", "protocol", "pins", "materials"})
      if (top.has(key))
        throw InputError(std::string("/") + key,
                         "a benchmark scene builds its own sheet: remove this key");
    scene.grid = {static_cast<double>(scene.benchmark_n - 1),
                  static_cast<double>(scene.benchmark_n - 1), scene.benchmark_n, scene.benchmark_n};
  } else {
    parse_sheet(top, materials, scene);
  }
  parse_pins(top, scene, scene.pins);
  parse_simulation(top, scene);
  parse_protocol(top, materials, base_dir, scene);
  parse_output(top, scene.output);
  if (scene.protocol.empty() && scene.simulation.is_static() && scene.pins.empty() &&
      scene.simulation.gravity != 0.0)
    throw InputError("/simulation/G",
                     "a free sheet under gravity has no static equilibrium: add "
                     "pins or set G to 0");
  return scene;
}

void apply_override(json& scene, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set " + assignment, "expected PATH=VALUE, e.g. simulation.steps=500");
  std::string pointer;
  const std::string path = assignment.substr(0, eq);
  size_t start = 0;
  while (start <= path.size()) {
    const size_t dot = std::min(path.find('.', start), path.size());
    const std::string part = path.substr(start, dot - start);
    if (part.empty())
      throw InputError("--set " + assignment, "empty component in path '" + path + "'");
    pointer += "/" + part;
    start = dot + 1;
  }
  const std::string text = assignment.substr(eq + 1);
  json value = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (value.is_discarded()) value = text;
  try {
    scene[json::json_pointer(pointer)] = value;
  } catch (const json::exception& e) {
    throw InputError("--set " + assignment, std::string("cannot set ") + pointer + ": " + e.what());
  }
}

Scene load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  const std::string name = file.string();
  json j = read_json_file(file, "scene");
  try {
    for (const auto& o : overrides) apply_override(j, o);
  } catch (const InputError& e) {
    throw InputError(name + ": " + e.where(), e.detail());
  }
  try {
    Scene s = parse_scene(j, file.parent_path());
    s.file = file;
    return s;
  } catch (const InputError& e) {
    throw InputError(e.where().empty() ? name : name + ": " + e.where(), e.detail());
  }
}

std::map<std::string, std::vector<std::string>> scene_known_keys() {
  return {{"", to_strings(kTopKeys)},
          {"/benchmark", to_strings(kBenchmarkKeys)},
          {"/sheet", to_strings(kSheetKeys)},
          {"/sheet/springs", to_strings(kSpringKeys)},
          {"/materials/*", to_strings(kMaterialKeys)},
          {"/pins/*", to_strings(kPinKeys)},
          {"/simulation", to_strings(kSimulationKeys)},
          {"/output", to_strings(kOutputKeys)},
          {"/output/camera", to_strings(kCameraKeys)},
          {"/protocol/*stretch", to_strings(kStretchKeys)},
          {"/protocol/*impregnate", to_strings(kImpregnateKeys)},
          {"/protocol/*release", to_strings(kReleaseKeys)},
          {"/protocol/*load", to_strings(kLoadKeys)},
          {"/protocol/*load/pins/*", to_strings(kPinKeys)},
          {"/protocol/*grow", to_strings(kGrowKeys)},
          {"/protocol/*add_springs", to_strings(kAddSpringsKeys)},
          {"/protocol/*cut", to_strings(kCutKeys)},
          {"/protocol/*curvature_map", to_strings(kCurvatureMapKeys)}};
}

}  // namespace membra
