#include "membra/io/scene.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "membra/core/units.hpp"
#include "membra/io/field_reader.hpp"
#include "membra/io/json_reader.hpp"
#include "membra/io/pattern_reader.hpp"
#include "membra/io/protocol_reader.hpp"

namespace membra {
namespace {

using nlohmann::json;

// Known keys, one list per object; scene_known_keys() exposes them for the schema test.
const std::vector<std::string_view> kBenchmarkKeys = {"problem", "n"};
const std::vector<std::string_view> kTopKeys = {"benchmark", "$schema",   "name", "description",
                                                "sheet",     "materials", "pins", "simulation",
                                                "protocol",  "output",    "model"};
const std::vector<std::string_view> kOutputKeys = {"frames", "camera", "image_size", "colormap"};
const std::vector<std::string_view> kCameraKeys = {"azimuth", "elevation"};
const std::vector<std::string_view> kSheetKeys = {"size",    "resolution", "material", "springs",
                                                  "bending", "outline",    "mesh"};
const std::vector<std::string_view> kMeshKeys = {"max_edge", "elements_across", "min_angle",
                                                 "grading", "tolerance"};
const std::vector<std::string_view> kSpringKeys = {"stretch", "shear", "flex", "flex_ratio"};
const std::vector<std::string_view> kMaterialKeys = {"preset",  "E",   "thickness",
                                                     "density", "law", "wrinkling"};
const std::vector<std::string_view> kPinKeys = {"corners", "edge", "point", "box"};
const std::vector<std::string_view> kSimulationKeys = {"self_contact",
                                                       "solver",
                                                       "K",
                                                       "G",
                                                       "T",
                                                       "D",
                                                       "spring_damping",
                                                       "steps",
                                                       "max_iterations",
                                                       "tolerance",
                                                       "stop_when_converged",
                                                       "path_tolerance",
                                                       "explore",
                                                       "multilevel",
                                                       "max_seconds",
                                                       "tangent_correction",
                                                       "support",
                                                       "ramp_seconds"};

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
    const std::string law = m.string("law", std::string(to_string(base.law)),
                                     {"neo_hookean", "mooney_rivlin", "stvk", "linear"});
    base.law = *membrane_law_from_name(law);
    base.wrinkling = *wrinkling_from_name(
        m.string("wrinkling", std::string(to_string(base.wrinkling)), {"full", "relaxed"}));
    if (base.wrinkling == Wrinkling::relaxed && !relaxable(base.law))
      throw InputError(m.pointer("wrinkling"),
                       "\"relaxed\" needs an incompressible law (neo_hookean or mooney_rivlin), "
                       "but the law is \"" +
                           law + "\"");
    out[name] = base;
  }
  return out;
}

// sheet.mesh: the continuum sheet's mesh settings, in mm and degrees.
void parse_mesh(const JsonObject& sheet, Scene& scene) {
  if (!sheet.has("mesh")) return;
  const JsonObject m = sheet.object("mesh", kMeshKeys);
  MeshSpec& spec = scene.mesh;
  spec.max_edge = m.number("max_edge", 0.0, Bounds::non_negative()) * units::mm;
  spec.elements_across =
      static_cast<int>(m.integer("elements_across", spec.elements_across, 1, 64));
  spec.min_angle_deg = m.number("min_angle", spec.min_angle_deg, Bounds::between(5.0, 33.0));
  spec.grading = m.number("grading", spec.grading, Bounds::between(0.05, 2.0));
  spec.tolerance =
      m.number("tolerance", spec.tolerance / units::mm, Bounds::between(1e-4, 1.0)) * units::mm;
}

// sheet.resolution: the lattice's grid [nx, ny]; a continuum sheet may leave it out.
void parse_resolution(const JsonObject& sheet, Scene& scene) {
  if (!sheet.has("resolution") && scene.model == SheetModel::continuum) return;
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
    // Three at least: plate bending needs three particles in a row; a 2 x 2 sheet has no
    // bending and floppy modes that leave its released form undetermined.
    if (n < 3 || n > kMaxNodesPerSide)
      throw InputError(ptr, "must be in [3, " + std::to_string(kMaxNodesPerSide) + "], got " +
                                std::to_string(n) +
                                (n == 2 ? " (plate bending needs three particles in a row)" : ""));
    (k == 0 ? scene.grid.nx : scene.grid.ny) = static_cast<int>(n);
  }
  // The homogenization (docs/model.md, "Homogenization") is for square cells.
  const double hx = scene.grid.width / units::mm / (scene.grid.nx - 1),
               hy = scene.grid.height / units::mm / (scene.grid.ny - 1);
  if (std::abs(hx / hy - 1.0) > 0.01) {
    std::ostringstream msg;
    msg << "cells must be square for the lattice to be isotropic, but the spacing is " << hx
        << " mm along x and " << hy << " mm along y; choose (nx-1)/(ny-1) = width/height";
    throw InputError(sheet.pointer("resolution"), msg.str());
  }
}

void parse_sheet(const JsonObject& top, const std::map<std::string, Material>& materials,
                 Scene& scene) {
  const JsonObject sheet = top.object("sheet", kSheetKeys);
  const auto size = sheet.numbers("size", 2, Bounds::positive());
  scene.grid.width = size[0] * units::mm;
  scene.grid.height = size[1] * units::mm;
  parse_resolution(sheet, scene);
  parse_mesh(sheet, scene);
  const std::string mat = sheet.string("material", "latex");
  const auto it = materials.find(mat);
  if (it == materials.end()) throw unknown_material(sheet.pointer("material"), mat, materials);
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

// simulation.self_contact: true (the defaults), false, or an object of gap (mm), pressure (kPa)
// and exclusion (mm, at least the gap).
void parse_self_contact(const JsonObject& s, SelfContactSpec& c) {
  if (!s.has("self_contact")) return;
  if (s.at("self_contact").is_boolean()) {
    c.on = s.boolean("self_contact", false);
    return;
  }
  const JsonObject o = s.object("self_contact", {"gap", "pressure", "exclusion"});
  c.on = true;
  c.gap = o.number("gap", c.gap / units::mm, Bounds{0.0, 100.0, true}) * units::mm;
  c.pressure = o.number("pressure", c.pressure / 1e3, Bounds{0.0, 1e6, true}) * 1e3;
  c.exclusion = o.number("exclusion", 3.0 * c.gap / units::mm, Bounds::positive()) * units::mm;
  if (c.exclusion < 2.0 * c.gap)
    throw InputError(o.pointer("exclusion"),
                     "pairs are listed up to two gaps apart, so neighbours in the material nearer "
                     "than that would press on each other in the plane: make the exclusion at "
                     "least twice the gap");
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
  sim.tangent_correction = s.boolean("tangent_correction", sim.tangent_correction);
  sim.support = s.string("support", to_string(sim.support), {"none", "table"}) == "table"
                    ? Support::table
                    : Support::none;
  if (sim.support == Support::table && !(sim.gravity > 0.0))
    throw InputError(s.pointer("support"),
                     "a table holds the piece against gravity: set simulation.G above 0 (e.g. "
                     "9.81 m/s^2)");
  parse_self_contact(s, sim.self_contact);
  sim.explore = static_cast<int>(s.integer("explore", sim.explore, 1, 1000));
  sim.multilevel = static_cast<int>(s.integer("multilevel", sim.multilevel, 0, kMaxNodesPerSide));
  if (sim.multilevel > 0 && sim.multilevel < 5)
    throw InputError(s.pointer("multilevel"),
                     "the coarsest grid needs at least 5 nodes along its longer side (0: off)");
  sim.max_seconds = s.number("max_seconds", sim.max_seconds, Bounds::between(0.0, 1e7));
  sim.ramp_seconds = s.number("ramp_seconds", sim.ramp_seconds, Bounds::between(0.0, 1e6));
  if (sim.ramp_seconds > 0.0 && sim.is_static())
    throw InputError(s.pointer("ramp_seconds"),
                     "a ramp in simulated time needs a time-stepping solver (rk4 or "
                     "symplectic_euler); the equilibrium solvers follow a path by `increments`");
  if (sim.ramp_seconds > static_cast<double>(sim.steps) * sim.dt * (1.0 + 1e-9)) {  // round-off
    std::ostringstream msg;
    msg << "the ramp (" << sim.ramp_seconds
        << " s) is longer than the run (steps x T = " << static_cast<double>(sim.steps) * sim.dt
        << " s): raise `steps` or shorten the ramp";
    throw InputError(s.pointer("ramp_seconds"), msg.str());
  }
  if (sim.multilevel > 0 && !sim.is_static())
    throw InputError(s.pointer("multilevel"),
                     "a multilevel release needs an equilibrium solver (newton or static), "
                     "not " +
                         solver);
  if (sim.explore > 1 && !sim.is_static())
    throw InputError(s.pointer("explore"),
                     "exploring the stable forms needs an equilibrium solver (static or newton), "
                     "not " +
                         solver);
}

}  // namespace

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
  out.colormap = colour_map_named(o.string("colormap", "diverging", {"diverging", "paper"}));
}

namespace {

// Self-contact is the continuum sheet's (its triangles), and Newton's, whose line search keeps
// the sheet from stepping through itself (docs/model.md, "Self-contact").
void check_self_contact(const Scene& scene) {
  if (!scene.simulation.self_contact.on) return;
  if (scene.model != SheetModel::continuum)
    throw InputError("/simulation/self_contact",
                     "self-contact needs the continuum sheet's triangles: set \"model\": "
                     "\"continuum\" (or --set model=continuum)");
  if (scene.simulation.solver != Solver::newton)
    throw InputError("/simulation/self_contact",
                     "self-contact is kept by Newton's line search: use \"solver\": \"newton\"");
}

}  // namespace

Scene parse_scene(const json& j, const std::filesystem::path& base_dir) {
  Scene scene;
  const JsonObject top(j, "", kTopKeys);
  scene.name = top.string("name", "untitled");
  scene.description = top.string("description", "");
  scene.model = top.string("model", "lattice", {"lattice", "continuum"}) == "continuum"
                    ? SheetModel::continuum
                    : SheetModel::lattice;
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
  check_self_contact(scene);
  if (scene.protocol.empty() && scene.simulation.is_static() && scene.pins.empty() &&
      scene.simulation.gravity != 0.0 && scene.simulation.support == Support::none)
    throw InputError("/simulation/G",
                     "a free sheet under gravity has no static equilibrium: add pins, rest it on "
                     "a table (simulation.support: table) or set G to 0");
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
    // A value a --set gave is the flag's fault, not the file's.
    for (const auto& o : overrides) {
      std::string pointer = "/" + o.substr(0, o.find('='));
      std::replace(pointer.begin(), pointer.end(), '.', '/');
      if (e.where() == pointer || e.where().rfind(pointer + "/", 0) == 0)
        throw InputError("--set " + o + " (on " + name + "): " + e.where(), e.detail());
    }
    throw InputError(e.where().empty() ? name : name + ": " + e.where(), e.detail());
  }
}

std::map<std::string, std::vector<std::string>> scene_known_keys() {
  std::map<std::string, std::vector<std::string>> keys = {
      {"", to_strings(kTopKeys)},
      {"/benchmark", to_strings(kBenchmarkKeys)},
      {"/sheet", to_strings(kSheetKeys)},
      {"/sheet/springs", to_strings(kSpringKeys)},
      {"/materials/*", to_strings(kMaterialKeys)},
      {"/pins/*", to_strings(kPinKeys)},
      {"/simulation", to_strings(kSimulationKeys)},
      {"/output", to_strings(kOutputKeys)},
      {"/output/camera", to_strings(kCameraKeys)},
      {"/protocol/*load/pins/*", to_strings(kPinKeys)}};
  keys.merge(protocol_known_keys());
  return keys;
}

}  // namespace membra
