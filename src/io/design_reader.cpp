#include "membra/io/design_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <utility>

#include "membra/core/input_error.hpp"
#include "membra/core/units.hpp"
#include "membra/geometry/square_grid.hpp"
#include "membra/io/json_reader.hpp"
#include "membra/io/obj.hpp"
#include "membra/io/pattern_reader.hpp"
#include "membra/io/scene.hpp"
#include "membra/io/scene_writer.hpp"

namespace membra {
namespace {
using nlohmann::json;

const std::vector<std::string_view> kDesignKeys = {
    "$schema", "name", "description", "target", "frame", "sheet", "materials", "resin", "design"};
const std::vector<std::string_view> kTargetKinds = {"cap", "saddle", "cylinder", "height_field",
                                                    "obj"};

void parse_target(const json& j, const std::string& ptr, const std::filesystem::path& base_dir,
                  TargetSpec& t) {
  if (!j.is_object() || j.size() != 1)
    throw InputError(ptr,
                     "the target is an object with exactly one key: cap, saddle, cylinder, "
                     "height_field or obj");
  const JsonObject outer(j, ptr, kTargetKinds);
  t.kind = j.begin().key();
  const std::string p = outer.pointer(t.kind);
  const json& body = j.begin().value();
  if (t.kind == "cap") {
    const JsonObject o(body, p, {"diameter", "height", "resolution"});
    t.size = o.number("diameter", std::nullopt, Bounds::positive()) * units::mm;
    t.height = o.number("height", std::nullopt, Bounds::positive()) * units::mm;
    t.resolution = static_cast<int>(o.integer("resolution", 41, 5, 401));
    if (t.height > 0.5 * t.size)
      throw InputError(o.pointer("height"), "a cap is at most a hemisphere: height <= diameter/2");
  } else if (t.kind == "saddle" || t.kind == "cylinder") {
    const JsonObject o(body, p, {"size", "height", "resolution"});
    t.size = o.number("size", std::nullopt, Bounds::positive()) * units::mm;
    t.height = o.number("height", std::nullopt, Bounds::positive()) * units::mm;
    t.resolution = static_cast<int>(o.integer("resolution", 41, 5, 401));
    if (t.kind == "cylinder" && t.height > 0.5 * t.size)
      throw InputError(o.pointer("height"), "a cylinder patch rises at most half its side");
  } else if (t.kind == "height_field") {
    const JsonObject o(body, p, {"size", "z", "resolution"});
    t.size = o.number("size", std::nullopt, Bounds::positive()) * units::mm;
    t.formula = o.string("z", std::nullopt);
    t.resolution = static_cast<int>(o.integer("resolution", 41, 5, 401));
  } else {
    const JsonObject o(body, p, {"file"});
    t.obj_file = (base_dir / o.string("file", std::nullopt)).string();
    // A regular file only: a device or a pipe (/dev/zero) would be read without end.
    std::ifstream in(t.obj_file);
    if (!std::filesystem::is_regular_file(t.obj_file) || !in)
      throw InputError(o.pointer("file"), t.obj_file + ": cannot open the OBJ file (not a file)");
    const ObjMesh mesh = read_obj(in, t.obj_file);
    t.obj_x = mesh.x;
    t.obj_triangles = mesh.triangles;
  }
  try {
    (void)make_target(t);  // fail now, naming the field, not after minutes of simulation
  } catch (const std::invalid_argument& e) {
    throw InputError(p, e.what());
  }
}

// The scene a design's stencils are simulated in, with one square of resin (the search puts its
// stencils in its place): read once when the design is, so that its materials and resolution are
// checked before any simulation.
json base_scene(const DesignSpec& spec, const json& materials) {
  const bool disk = spec.target.kind == "cap";
  const double wx = spec.frame / spec.lambda.x() / units::mm,
               wy = spec.frame / spec.lambda.y() / units::mm;
  const auto [nx, ny] = square_grid(wx, wy, spec.resolution);
  json scene = {
      {"name", spec.name},
      {"description", "Stencil designed by `membra design` for a " + spec.target.kind + " target"},
      {"sheet",
       {{"size", {wx, wy}},
        {"resolution", {nx, ny}},
        {"material", spec.material},
        {"outline", disk ? "disk" : "rectangle"}}},
      {"simulation",
       {{"solver", std::string(solver_name(spec.solver))},
        {"G", 0.0},
        {"tolerance", spec.tolerance}}},
      {"protocol", json::array()}};
  if (!materials.is_null()) scene["materials"] = materials;
  json& p = scene["protocol"];
  p.push_back({{"step", "stretch"}, {"lambda", {spec.lambda.x(), spec.lambda.y()}}});
  p.push_back(
      {{"step", "impregnate"},
       {"material", spec.resin},
       {"resin_side", spec.resin_side == "convex" ? "top" : spec.resin_side},
       {"bilayer", spec.bilayer},
       {"pattern", {{"polygon", {{"points", {{90, 90}, {110, 90}, {110, 110}, {90, 110}}}}}}}});
  p.push_back({{"step", "release"}, {"increments", spec.increments}});
  return scene;
}

// /frame: its size and the pre-stretch.
void read_frame(const JsonObject& top, DesignSpec& s) {
  if (!top.has("frame")) return;
  const JsonObject f = top.object("frame", {"size", "lambda"});
  s.frame = f.number("size", 200.0, Bounds::positive()) * units::mm;
  if (f.has("lambda")) {
    const auto l = f.numbers("lambda", 2, Bounds{1.0, 10.0, false});
    s.lambda = Vec2(l[0], l[1]);
    if (!(s.lambda.prod() > 1.0))
      throw InputError(f.pointer("lambda"),
                       "at least one direction must be stretched (lambda > 1): without "
                       "pre-stretch resin changes nothing");
  }
}

// /resin/darts: how many, only for a darts layout, and no more than leave each dart and each
// piece of resin between two the minimum feature (around the rim for darts, across the frame for
// fisheye darts, which need a square sheet).
void read_darts(const JsonObject& o, DesignSpec& s) {
  if (o.has("darts") && !s.layout.has_darts())
    throw InputError(o.pointer("darts"),
                     "\"darts\" counts darts: set \"layout\": \"darts\" or "
                     "\"fisheye_darts\"");
  s.layout.darts = static_cast<int>(o.integer("darts", s.layout.darts, 3, 64));
  const double room = (s.layout.kind == "darts" ? std::numbers::pi : 1.0) * s.frame;
  if (s.layout.has_darts() && room / s.layout.darts < 2.0 * s.layout.min_feature)
    throw InputError(o.pointer("darts"),
                     "too many darts for this frame: each needs room for a "
                     "dart and a piece of resin, min_feature wide each");
  if (o.has("dart_centres")) {
    if (s.layout.kind != "darts")
      throw InputError(o.pointer("dart_centres"),
                       "\"dart_centres\" place darts about several points: set \"layout\": "
                       "\"darts\"");
    if (o.at("dart_centres").is_string()) {
      if (o.at("dart_centres") != "auto")
        throw InputError(o.pointer("dart_centres"),
                         "expected \"auto\" or an array of [x, y] points (mm)");
      s.layout.auto_centres = true;
    } else {
      s.layout.centres = read_points(o, "dart_centres", 1);
    }
    if (s.layout.centres.size() > 16)
      throw InputError(o.pointer("dart_centres"), "at most 16 centres");
    for (size_t i = 0; i < s.layout.centres.size(); ++i)
      for (size_t j = 0; j < i; ++j)
        if ((s.layout.centres[i] - s.layout.centres[j]).norm() < 4.0 * s.layout.min_feature)
          throw InputError(o.pointer("dart_centres") + "/" + std::to_string(i),
                           "closer to centre " + std::to_string(j) +
                               " than four times min_feature: their darts would have no room");
  }
  if (s.layout.kind == "fisheye_darts" && s.target.kind == "cap")
    throw InputError(o.pointer("layout"),
                     "fisheye darts cross a square sheet; a cap's is a disk "
                     "(\"darts\" make domes)");
}

// /resin: the material, its face, the stencil's cell and minimum feature.
void read_resin(const JsonObject& top, DesignSpec& s) {
  if (!top.has("resin")) return;
  const JsonObject o = top.object("resin", {"material", "min_feature", "cell", "resin_side",
                                            "bilayer", "layout", "darts", "dart_centres"});
  s.resin = o.string("material", s.resin);
  s.resin_side = o.string("resin_side", "top", {"top", "bottom", "convex"});
  s.bilayer = o.boolean("bilayer", false);
  if (s.resin_side == "convex" && !s.bilayer)
    throw InputError(o.pointer("resin_side"),
                     "\"convex\" lays each piece on the face the target bulges towards, which "
                     "only a coat on one face makes curl: set \"bilayer\": true");
  s.layout.min_feature = o.number("min_feature", 4.0, Bounds::positive()) * units::mm;
  s.layout.cell = o.number("cell", 20.0, Bounds::positive()) * units::mm;
  if (s.layout.cell < 2.0 * s.layout.min_feature)
    throw InputError(o.pointer("cell"),
                     "the cell must be at least twice min_feature (a piece and a gap)");
  if (s.layout.cell > 0.5 * s.frame)
    throw InputError(o.pointer("cell"), "the cell must be at most half the frame");
  s.layout.kind = o.string("layout", "squares", {"squares", "darts", "fisheye_darts"});
  if (s.layout.kind == "fisheye_darts" && s.resin_side == "convex")
    throw InputError(o.pointer("resin_side"),
                     "fisheye darts lie on one face (\"convex\" cuts only \"darts\" through a "
                     "coat on either face)");
  read_darts(o, s);
}

// /design: the search's budget and the simulations' solver.
void read_design_settings(const JsonObject& top, DesignSpec& s) {
  if (!top.has("design")) return;
  const JsonObject o =
      top.object("design", {"method", "evaluations", "budget", "solver", "tolerance", "increments",
                            "density_cell", "smoothing", "flattening", "stencil_trials",
                            "piece_evaluations", "search_stretch"});
  s.method = o.string("method", s.method, {"adjoint", "pattern_search"});
  // The adjoint's evaluations are cheap warm starts: it takes more of them by default.
  s.evaluations = static_cast<int>(
      o.integer("evaluations", s.method == "adjoint" ? 80 : s.evaluations, 1, 10000));
  s.density_cell =
      o.number("density_cell", s.density_cell / units::mm, Bounds::positive()) * units::mm;
  if (s.density_cell > 0.5 * s.frame)
    throw InputError(o.pointer("density_cell"), "the density cell must be at most half the frame");
  s.smoothing = o.number("smoothing", s.smoothing, Bounds::between(0.0, 1e6));
  s.flattening = o.string("flattening", s.flattening, {"conformal", "projection"});
  s.stencil_trials = static_cast<int>(o.integer("stencil_trials", s.stencil_trials, 1, 5));
  s.piece_evaluations =
      static_cast<int>(o.integer("piece_evaluations", s.piece_evaluations, 0, 1000));
  if (s.method == "adjoint" && s.bilayer)
    throw InputError("/resin/bilayer",
                     "the adjoint method does not place a coat on one face yet: use "
                     "\"method\": \"pattern_search\" for a bilayer");
  if (s.method == "adjoint" && s.layout.has_darts())
    throw InputError("/resin/layout",
                     "the adjoint method lays out squares: use \"method\": \"pattern_search\" "
                     "for darts");
  s.search_stretch = o.boolean("search_stretch", false);
  if (s.method == "adjoint" && s.search_stretch)
    throw InputError(o.pointer("search_stretch"),
                     "the adjoint method keeps the pre-stretch: use \"method\": "
                     "\"pattern_search\" to search it");
  s.budget = o.number("budget", s.budget, Bounds::positive());
  std::vector<std::string_view> equilibrium;
  for (const SolverInfo& info : solver_table())
    if (info.equilibrium && info.in_scenes) equilibrium.push_back(info.name);
  s.solver = *solver_from_name(o.string("solver", std::string(solver_name(s.solver)), equilibrium));
  s.tolerance = o.number("tolerance", s.tolerance, Bounds{0.0, 1.0, true});
  s.increments = static_cast<int>(o.integer("increments", s.increments, 1, 1000));
}

}  // namespace

DesignSpec parse_design(const json& j, const std::filesystem::path& base_dir) {
  DesignSpec s;
  const JsonObject top(j, "", kDesignKeys);
  s.name = top.string("name", "design");
  if (!top.has("target")) throw InputError("/target", "a design needs a target surface");
  parse_target(top.at("target"), "/target", base_dir, s.target);
  read_frame(top, s);
  if (top.has("sheet")) {
    const JsonObject o = top.object("sheet", {"resolution", "material"});
    s.resolution = static_cast<int>(o.integer("resolution", s.resolution, 5, 201));
    s.material = o.string("material", s.material);
  }
  read_resin(top, s);
  read_design_settings(top, s);
  if (s.target.kind != "obj" && s.target.size > s.frame)
    throw InputError("/target",
                     "the target is wider than the frame: the released sheet is "
                     "always smaller than the frame it was stretched on");
  // The scene it makes must be valid too (materials, resolution).
  try {
    s.scene =
        parse_scene(base_scene(s, top.has("materials") ? top.at("materials") : json()), base_dir);
  } catch (const InputError& e) {
    throw InputError("(the scene this design makes) " + e.where(), e.detail());
  }
  return s;
}

DesignSpec load_design(const std::filesystem::path& file) {
  const std::string name = file.string();
  const json j = read_json_file(file, "design");
  try {
    DesignSpec s = parse_design(j, file.parent_path());
    s.file = file;
    return s;
  } catch (const InputError& e) {
    throw InputError(name + ": " + e.where(), e.detail());
  }
}

json design_scene(const DesignSpec& spec, const Stencil& stencil) {
  return write_scene(stencil_scene(spec, stencil));
}

}  // namespace membra
