#include "membra/io/protocol_reader.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "membra/core/did_you_mean.hpp"
#include "membra/core/units.hpp"
#include "membra/io/field_reader.hpp"
#include "membra/io/pattern_reader.hpp"

namespace membra {
namespace {

using nlohmann::json;

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

// What the steps so far did, as far as the next one's checks need to know.
struct Progression {
  const Scene& scene;
  const std::map<std::string, Material>& materials;
  const std::filesystem::path& base_dir;
  Vec2 stretch{1.0, 1.0};  // product of the stretches so far
  bool pinned = false, framed = false;
  bool released = false;  // the sheet has left its frame: where it lies is the run's to find
  double gravity = 0.0;

  // The stretched frame (m): where patterns are placed.
  Vec2 frame() const {
    return Vec2(stretch.x() * scene.grid.width, stretch.y() * scene.grid.height);
  }
  void check_equilibrium(const std::string& ptr) const {
    if (scene.simulation.is_static() && !pinned && !framed && gravity != 0.0 &&
        scene.simulation.support == Support::none)
      throw InputError(ptr,
                       "a free sheet under gravity has no static equilibrium: pin it (a load "
                       "step with pins), rest it on a table (simulation.support: table) or set "
                       "simulation.G (or the load step's gravity) to 0");
  }
};

// increments, perturbation and seed: how a step that changes the sheet's shape is followed.
PathSettings read_path(const JsonObject& o) {
  PathSettings p;
  p.increments = static_cast<int>(o.integer("increments", p.increments, 1, 100000));
  p.perturbation =
      o.number("perturbation", p.perturbation / units::mm, Bounds::non_negative()) * units::mm;
  p.seed = static_cast<std::uint64_t>(o.integer("seed", 1, 0, 2'000'000'000L));
  return p;
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

FrameEdges read_hold(const JsonObject& o) {
  FrameEdges hold;
  if (!o.has("hold")) return hold;
  const auto& h = o.at("hold");
  if (!h.is_array() || h.empty())
    throw InputError(o.pointer("hold"),
                     "expected a non-empty array of edges: left, right, bottom, top");
  hold = {false, false, false, false};
  for (size_t e = 0; e < h.size(); ++e) {
    const std::string edge = h[e].is_string() ? h[e].get<std::string>() : "";
    if (edge == "left")
      hold.left = true;
    else if (edge == "right")
      hold.right = true;
    else if (edge == "bottom")
      hold.bottom = true;
    else if (edge == "top")
      hold.top = true;
    else
      throw InputError(o.pointer("hold") + "/" + std::to_string(e),
                       "expected one of left, right, bottom, top, got " + h[e].dump());
  }
  return hold;
}

// A frame cannot push a membrane: a stretch may contract one direction no further than a free
// latex sheet (incompressible) contracts when the other is stretched, 1 / sqrt(lambda_other),
// as exp2's [1.5, 0.8165] does. Below that the latex would be compressed and only wrinkle.
void check_not_compressed(const JsonObject& o, const Vec2& stretch) {
  for (int d = 0; d < 2; ++d) {
    const double free = 1.0 / std::sqrt(stretch[1 - d]);
    if (stretch[d] >= std::min(1.0, free) * (1.0 - 1e-4)) continue;
    std::ostringstream msg;
    msg << "a stretch of " << stretch[d] << " along " << (d == 0 ? "x" : "y")
        << " would compress the latex: a frame can only pull a membrane, and a free sheet "
           "stretched "
        << stretch[1 - d] << " along " << (d == 0 ? "y" : "x") << " contracts to "
        << std::min(1.0, free)
        << " at most (lambda >= 1, or the free contraction 1/sqrt of the "
           "other lambda; exp2 uses [1.5, 0.8165])";
    throw InputError(o.pointer("lambda"), msg.str());
  }
}

StretchStep read_stretch(const JsonObject& o, Progression& at) {
  StretchStep s;
  const auto l = o.numbers("lambda", 2, Bounds{0.0, 10.0, true});
  s.lambda = Vec2(l[0], l[1]);
  s.hold = read_hold(o);
  at.stretch = at.stretch.cwiseProduct(s.lambda);
  check_not_compressed(o, at.stretch);
  at.framed = true;
  at.released = false;  // on a frame again: the box check holds
  return s;
}

ImpregnateStep read_impregnate(const JsonObject& o, const Progression& at) {
  ImpregnateStep s;
  const Vec2 frame = at.frame();
  s.pattern_spec = read_pattern_spec(o.at("pattern"), o.pointer("pattern"), at.base_dir);
  s.pattern = make_pattern(s.pattern_spec, frame);
  const Box2 inside = s.pattern->bounds().intersect({Vec2::Zero(), frame});
  if (inside.empty() || inside.max.x() <= inside.min.x() || inside.max.y() <= inside.min.y()) {
    std::ostringstream msg;
    msg << "the pattern lies outside the frame [0, " << frame.x() / units::mm << "] x [0, "
        << frame.y() / units::mm << "] mm (frame coordinates: the stretched sheet)";
    throw InputError(o.pointer("pattern"), msg.str());
  }
  const std::string mat = o.string("material", "epoxy");
  const auto it = at.materials.find(mat);
  if (it == at.materials.end()) throw unknown_material(o.pointer("material"), mat, at.materials);
  s.resin = it->second;
  s.resin_side = o.string("resin_side", "top", {"top", "bottom"}) == "top" ? 1 : -1;
  s.bilayer = o.boolean("bilayer", false);
  // The hinges carry only the linear part of the plate energy; the bending elements the
  // quadratic one that stops the curl.
  if (s.bilayer && !at.scene.sheet.bending)
    throw InputError(o.pointer("bilayer"),
                     "a bilayer needs the sheet's bending (sheet.bending is false)");
  return s;
}

ReleaseStep read_release(const JsonObject& o, Progression& at) {
  ReleaseStep s{read_path(o)};
  if (!at.framed) throw InputError(o.pointer(), "release needs a stretch step before it");
  at.framed = false;
  at.released = true;
  at.check_equilibrium(o.pointer());
  return s;
}

// The growth factor, checked positive at every spring midpoint of the grid (the points where it
// will be evaluated) so that a bad formula fails before any solve.
void check_growth_factor(const JsonObject& o, const GridSpec& grid, const ScalarField& factor) {
  const Vec2 size(grid.width, grid.height);
  const int nx = 2 * grid.nx - 1, ny = 2 * grid.ny - 1;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Vec2 p(size.x() * i / (nx - 1), size.y() * j / (ny - 1));
      double f = 0.0;
      try {
        f = factor(p);
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
}

GrowDirection grow_direction(const std::string& dir) {
  return dir == "x"        ? GrowDirection::x
         : dir == "y"      ? GrowDirection::y
         : dir == "radial" ? GrowDirection::radial
         : dir == "hoop"   ? GrowDirection::hoop
                           : GrowDirection::all;
}

GrowStep read_grow(const JsonObject& o, const Progression& at) {
  GrowStep s;
  const Vec2 size(at.scene.grid.width, at.scene.grid.height);
  FormulaContext ctx;
  ctx.size = size;
  ctx.center = 0.5 * size;
  if (o.has("center")) {
    const auto c = o.numbers("center", 2);
    ctx.center = Vec2(c[0], c[1]) * units::mm;
  }
  GrowSpec& g = s.grow;
  g.center = ctx.center;
  s.factor = read_field_spec(o.at("factor"), o.pointer("factor"), at.base_dir);
  g.factor = build_field(s.factor, o.pointer("factor"), ctx);
  check_growth_factor(o, at.scene.grid, g.factor);
  const std::string family =
      o.string("family", "all", {"all", "stretch", "shear", "flex", "added"});
  if (family != "all") g.family = spring_family(family);
  g.direction = grow_direction(o.string("direction", "all", {"all", "x", "y", "radial", "hoop"}));
  if (o.has("region")) {
    s.region = read_pattern_spec(o.at("region"), o.pointer("region"), at.base_dir);
    g.region = make_pattern(*s.region, size);
  }
  s.path = read_path(o);
  at.check_equilibrium(o.pointer());
  return s;
}

CurvatureMapStep read_curvature_map(const JsonObject& o, const Progression& at) {
  CurvatureMapStep s;
  const GridSpec& grid = at.scene.grid;
  FormulaContext ctx;
  ctx.size = Vec2(grid.width, grid.height);
  ctx.center = 0.5 * ctx.size;
  s.field = read_field_spec(o.at("K"), o.pointer("K"), at.base_dir);
  const ScalarField per_mm2 = build_field(s.field, o.pointer("K"), ctx);
  s.curvature = [per_mm2](const Vec2& p) { return per_mm2(p) / (units::mm * units::mm); };
  for (int jj = 0; jj < grid.ny; ++jj)
    for (int ii = 0; ii < grid.nx; ++ii) {
      const Vec2 q(grid.width * ii / (grid.nx - 1), grid.height * jj / (grid.ny - 1));
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
  s.path = read_path(o);
  at.check_equilibrium(o.pointer());
  return s;
}

AddSpringsStep read_add_springs(const JsonObject& o, const Progression& at) {
  AddSpringsStep s;
  s.region = read_pattern_spec(o.at("pattern"), o.pointer("pattern"), at.base_dir);
  s.add.region = make_pattern(s.region, at.frame());
  const std::string along = o.string("along", "stretch", {"stretch", "shear", "flex", "any"});
  s.add.along = along == "any" ? std::optional<SpringFamily>() : spring_family(along);
  s.along_given = o.has("along") && along != "any";
  s.add.count = static_cast<int>(o.integer("count", 1, 1, 1000));
  s.add.stiffness = o.has("stiffness")
                        ? o.number("stiffness", std::nullopt, Bounds::positive()) * units::N_per_mm
                        : 0.0;
  s.add.rest_factor = o.number("rest_factor", 1.0, Bounds{0.0, 10.0, true});
  s.path = read_path(o);
  at.check_equilibrium(o.pointer());
  return s;
}

CutStep read_cut(const JsonObject& o, const Progression& at) {
  CutStep s;
  if (!o.has("line") && !o.has("hole"))
    throw InputError(o.pointer(), "a cut needs a \"line\" (polyline, mm) or a \"hole\" (pattern)");
  // Where the sheet is now: the stretched frame, or the natural sheet when no frame holds it.
  const Vec2 frame = at.framed ? at.frame() : Vec2(at.scene.grid.width, at.scene.grid.height);
  const Box2 sheet_box{Vec2::Zero(), frame};
  // After the release the sheet lies where its form took it: the run checks the cut against that
  // (the lattice: it crosses a spring; the continuum: model/top_view.hpp).
  auto outside = [&](const Box2& b) { return !at.released && b.intersect(sheet_box).empty(); };
  std::ostringstream where;
  where << "[0, " << frame.x() / units::mm << "] x [0, " << frame.y() / units::mm << "] mm";
  if (o.has("line")) {
    s.line = read_polyline(o, "line");
    Box2 b;
    for (const Vec2& q : s.line) b.extend(q);
    if (outside(b))
      throw InputError(o.pointer("line"), "the cut lies outside the sheet " + where.str());
  }
  if (o.has("hole")) {
    s.hole_spec = read_pattern_spec(o.at("hole"), o.pointer("hole"), at.base_dir);
    s.hole = make_pattern(*s.hole_spec, frame);
    if (outside(s.hole->bounds()))
      throw InputError(o.pointer("hole"), "the hole lies outside the sheet " + where.str());
  }
  return s;
}

LoadStep read_load(const JsonObject& o, Progression& at) {
  LoadStep s;
  if (o.has("gravity")) s.gravity = o.number("gravity", std::nullopt, Bounds::between(-1e4, 1e4));
  if (s.gravity && !(*s.gravity > 0.0) && at.scene.simulation.support == Support::table)
    throw InputError(o.pointer("gravity"),
                     "the piece rests on a table (simulation.support), which holds it only "
                     "against gravity above 0");
  if (s.gravity) at.gravity = *s.gravity;
  parse_pins(o, at.scene, s.pins);
  at.pinned = at.pinned || !s.pins.empty();
  at.check_equilibrium(o.pointer());
  return s;
}

// The step at `ptr`, read by the reader of its kind.
ProtocolStep read_step(const json& j, const std::string& ptr, Progression& at) {
  if (!j.is_object() || !j.contains("step"))
    throw InputError(ptr,
                     "expected an object with a \"step\" key (stretch, impregnate, release, load, "
                     "grow, add_springs, cut, curvature_map)");
  // Any step's key passes here; each kind then checks its own.
  std::vector<std::string_view> all_keys;
  for (const auto* keys : {&kStretchKeys, &kImpregnateKeys, &kReleaseKeys, &kLoadKeys, &kGrowKeys,
                           &kAddSpringsKeys, &kCutKeys, &kCurvatureMapKeys})
    all_keys.insert(all_keys.end(), keys->begin(), keys->end());
  std::sort(all_keys.begin(), all_keys.end());
  all_keys.erase(std::unique(all_keys.begin(), all_keys.end()), all_keys.end());
  const std::string kind = JsonObject(j, ptr, all_keys)
                               .string("step", std::nullopt,
                                       {"stretch", "impregnate", "release", "load", "grow",
                                        "add_springs", "cut", "curvature_map"});
  ProtocolStep step;
  step.pointer = ptr;
  if (kind == "stretch") step.step = read_stretch(JsonObject(j, ptr, kStretchKeys), at);
  if (kind == "impregnate") step.step = read_impregnate(JsonObject(j, ptr, kImpregnateKeys), at);
  if (kind == "release") step.step = read_release(JsonObject(j, ptr, kReleaseKeys), at);
  if (kind == "grow") step.step = read_grow(JsonObject(j, ptr, kGrowKeys), at);
  if (kind == "curvature_map")
    step.step = read_curvature_map(JsonObject(j, ptr, kCurvatureMapKeys), at);
  if (kind == "add_springs") step.step = read_add_springs(JsonObject(j, ptr, kAddSpringsKeys), at);
  if (kind == "cut") step.step = read_cut(JsonObject(j, ptr, kCutKeys), at);
  if (kind == "load") step.step = read_load(JsonObject(j, ptr, kLoadKeys), at);
  return step;
}

}  // namespace

InputError unknown_material(const std::string& pointer, const std::string& name,
                            const std::map<std::string, Material>& materials) {
  std::vector<std::string_view> known;
  std::string list;
  for (const auto& [key, material] : materials) {
    known.push_back(key);
    list += (list.empty() ? "" : ", ") + key;
  }
  return InputError(pointer, "unknown material '" + name + "'" + did_you_mean(name, known) +
                                 "; known: " + list +
                                 " (define others under /materials, with a preset to start from)");
}

void parse_protocol(const JsonObject& top, const std::map<std::string, Material>& materials,
                    const std::filesystem::path& base_dir, Scene& scene) {
  if (!top.has("protocol")) return;
  const auto& arr = top.at("protocol");
  if (!arr.is_array()) throw InputError("/protocol", "expected an array of steps");
  Progression at{scene, materials, base_dir};
  at.pinned = !scene.pins.empty();
  at.gravity = scene.simulation.gravity;
  for (size_t i = 0; i < arr.size(); ++i)
    scene.protocol.push_back(read_step(arr[i], "/protocol/" + std::to_string(i), at));
}

std::map<std::string, std::vector<std::string>> protocol_known_keys() {
  return {{"/protocol/*stretch", to_strings(kStretchKeys)},
          {"/protocol/*impregnate", to_strings(kImpregnateKeys)},
          {"/protocol/*release", to_strings(kReleaseKeys)},
          {"/protocol/*load", to_strings(kLoadKeys)},
          {"/protocol/*grow", to_strings(kGrowKeys)},
          {"/protocol/*add_springs", to_strings(kAddSpringsKeys)},
          {"/protocol/*cut", to_strings(kCutKeys)},
          {"/protocol/*curvature_map", to_strings(kCurvatureMapKeys)}};
}

}  // namespace membra
