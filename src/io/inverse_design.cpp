#include "membra/io/inverse_design.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "membra/core/input_error.hpp"
#include "membra/core/units.hpp"
#include "membra/io/json_reader.hpp"
#include "membra/io/obj.hpp"
#include "membra/io/scene.hpp"
#include "membra/measure/curvature.hpp"
#include "membra/solve/solve_report.hpp"

namespace membra {
namespace {
using nlohmann::json;

const std::vector<std::string_view> kTopKeys = {
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
    std::ifstream in(t.obj_file);
    if (!in) throw InputError(o.pointer("file"), t.obj_file + ": cannot open the OBJ file");
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

// Area of the natural sheet (square, or the disk inscribed in it).
double natural_area(const DesignSpec& s, bool disk) {
  const double wx = s.frame / s.lambda.x(), wy = s.frame / s.lambda.y();
  return disk ? 0.25 * std::acos(-1.0) * wx * wy : wx * wy;
}

struct Evaluation {
  Stencil stencil;
  json scene;
  RunResult run;
  ShapeError error;
  double rms = std::numeric_limits<double>::infinity();  // % of the diameter
  double max = std::numeric_limits<double>::infinity();
  std::string note;
};

}  // namespace

double DensityParameters::operator()(const Vec2& p, const Box2& frame) const {
  const Vec2 c = 0.5 * (frame.min + frame.max), h = 0.5 * (frame.max - frame.min);
  const double u = (p.x() - c.x()) / h.x(), v = (p.y() - c.y()) / h.y();
  // r^2 - 1/2 and x^2 - y^2 average to about zero over the frame: the mean stays the mean.
  return mean + radial * (u * u + v * v - 0.5) + anisotropy * (u * u - v * v);
}

DesignSpec parse_design(const json& j, const std::filesystem::path& base_dir) {
  DesignSpec s;
  const JsonObject top(j, "", kTopKeys);
  s.name = top.string("name", "design");
  if (!top.has("target")) throw InputError("/target", "a design needs a target surface");
  parse_target(top.at("target"), "/target", base_dir, s.target);
  if (top.has("frame")) {
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
  if (top.has("sheet")) {
    const JsonObject o = top.object("sheet", {"resolution", "material"});
    s.resolution = static_cast<int>(o.integer("resolution", s.resolution, 5, 201));
    s.material = o.string("material", s.material);
  }
  if (top.has("materials")) s.materials = top.at("materials");
  if (top.has("resin")) {
    const JsonObject o =
        top.object("resin", {"material", "min_feature", "cell", "resin_side", "bilayer"});
    s.resin = o.string("material", s.resin);
    s.resin_side = o.string("resin_side", "top", {"top", "bottom"});
    s.bilayer = o.boolean("bilayer", false);
    s.layout.min_feature = o.number("min_feature", 4.0, Bounds::positive()) * units::mm;
    s.layout.cell = o.number("cell", 20.0, Bounds::positive()) * units::mm;
    if (s.layout.cell < 2.0 * s.layout.min_feature)
      throw InputError(o.pointer("cell"),
                       "the cell must be at least twice min_feature (a piece and a gap)");
    if (s.layout.cell > 0.5 * s.frame)
      throw InputError(o.pointer("cell"), "the cell must be at most half the frame");
  }
  if (top.has("design")) {
    const JsonObject o =
        top.object("design", {"evaluations", "budget", "solver", "tolerance", "increments"});
    s.evaluations = static_cast<int>(o.integer("evaluations", s.evaluations, 1, 10000));
    s.budget = o.number("budget", s.budget, Bounds::positive());
    s.solver = o.string("solver", s.solver, {"static", "newton"});
    s.tolerance = o.number("tolerance", s.tolerance, Bounds{0.0, 1.0, true});
    s.increments = static_cast<int>(o.integer("increments", s.increments, 1, 1000));
  }
  if (s.target.kind != "obj" && s.target.size > s.frame)
    throw InputError("/target",
                     "the target is wider than the frame: the released sheet is "
                     "always smaller than the frame it was stretched on");
  // The scene it makes must be valid too (materials, resolution): check it once now.
  try {
    Stencil probe;  // one square of resin, so that the resin material is checked too
    probe.json = {{"polygon", {{"points", {{90, 90}, {110, 90}, {110, 110}, {90, 110}}}}}};
    (void)parse_scene(design_scene(s, probe), base_dir);
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
  const bool disk = spec.target.kind == "cap";
  const double wx = spec.frame / spec.lambda.x() / units::mm,
               wy = spec.frame / spec.lambda.y() / units::mm;
  // `resolution` particles along the shorter side, square cells (as many as fit) along the other.
  const int n = spec.resolution;
  const int nx = wx <= wy ? n : static_cast<int>(std::lround((n - 1) * wx / wy)) + 1;
  const int ny = wy <= wx ? n : static_cast<int>(std::lround((n - 1) * wy / wx)) + 1;
  json scene = {
      {"name", spec.name},
      {"description", "Stencil designed by `membra design` for a " + spec.target.kind + " target"},
      {"sheet",
       {{"size", {wx, wy}},
        {"resolution", {nx, ny}},
        {"material", spec.material},
        {"outline", disk ? "disk" : "rectangle"}}},
      {"simulation", {{"solver", spec.solver}, {"G", 0.0}, {"tolerance", spec.tolerance}}},
      {"protocol", json::array()}};
  if (!spec.materials.is_null()) scene["materials"] = spec.materials;
  json& p = scene["protocol"];
  p.push_back({{"step", "stretch"}, {"lambda", {spec.lambda.x(), spec.lambda.y()}}});
  if (!stencil.json.is_null())
    p.push_back({{"step", "impregnate"},
                 {"material", spec.resin},
                 {"resin_side", spec.resin_side},
                 {"bilayer", spec.bilayer},
                 {"pattern", stencil.json}});
  p.push_back({{"step", "release"}, {"increments", spec.increments}});
  return scene;
}

DesignResult run_design(const DesignSpec& spec,
                        const std::function<void(const DesignIteration&)>& progress) {
  const Stopwatch clock;
  DesignResult r;
  r.spec = spec;
  r.target = make_target(spec.target);
  const TargetSurface& target = r.target;
  const bool disk = target.disk;
  const Box2 frame{Vec2::Zero(), Vec2(spec.frame, spec.frame)};
  const Vec2 centre = 0.5 * frame.max;
  const auto inside = [&](const Vec2& p) {
    return !disk || (p - centre).norm() <= 0.5 * spec.frame;
  };
  const std::filesystem::path base = spec.file.parent_path();

  // Where to start, from mechanics. Resin keeps the stretched size, latex returns to its
  // natural size: the released area lies between the natural and the frame's, roughly in
  // proportion to the resin's share. And a metric with Gaussian curvature K needs the scale to
  // fall off as -K r^2 / 4 from the centre (Liouville's equation for small K r^2): more resin in
  // the middle for a dome (K > 0), at the rim for a saddle (K < 0).
  const double a_nat = natural_area(spec, disk), a_frame = a_nat * spec.lambda.prod();
  const double share = (target.area - a_nat) / (a_frame - a_nat);
  std::ostringstream why;
  if (share > 1.02) {
    why << "the target's area (" << target.area / (units::mm * units::mm)
        << " mm^2) is more than the stretched frame's (" << a_frame / (units::mm * units::mm)
        << " mm^2): resin keeps the stretched size and latex shrinks, so the released sheet is "
           "never larger than the frame. Use a larger frame or pre-stretch, or a smaller target.";
  } else if (share < -0.02) {
    why << "the target's area (" << target.area / (units::mm * units::mm)
        << " mm^2) is less than the natural sheet's (" << a_nat / (units::mm * units::mm)
        << " mm^2): the latex cannot shrink below its natural size. Use less pre-stretch or a "
           "larger target.";
  }
  r.reachable = why.str().empty();
  r.message = why.str();
  {
    // What a flat sheet of the target's footprint scores: a design is only worth its error
    // below this.
    Points flat = target.x;
    flat.row(2).setZero();
    r.flat_error = 100.0 * compare_shapes(flat, target.triangles, target).rms / target.diameter;
  }
  GaussianCurvature k = gaussian_curvature(target.x, target.triangles);
  const double k_mean = k.total / target.area;
  const double half = 0.5 * std::sqrt(a_nat);
  const double lam = std::sqrt(spec.lambda.prod());
  r.start.mean = std::clamp(share, 0.0, 1.0);
  r.start.radial = std::clamp(-k_mean * half * half / (4.0 * (1.0 - 1.0 / lam)), -1.0, 1.0);
  r.start.anisotropy = 0.0;

  auto evaluate = [&](const DensityParameters& d) {
    Evaluation e;
    e.stencil =
        layout_stencil([&](const Vec2& p) { return d(p, frame); }, frame, spec.layout, inside);
    e.scene = design_scene(spec, e.stencil);
    try {
      e.run = run_scene(parse_scene(e.scene, base));
    } catch (const InputError& err) {
      // E.g. squares so small on a coarse grid that they cover no spring: not a form.
      e.note = std::string("not simulated: ") + err.what();
      return e;
    }
    if (e.run.solve.diverged) {
      e.note = "diverged";
      return e;
    }
    if (!e.run.solve.converged) e.note = "did not converge";
    const Membrane& m = e.run.prepared.membrane;
    e.error = compare_shapes(m.state.x, m.sheet.triangles, target);
    e.rms = 100.0 * e.error.rms / target.diameter;
    e.max = 100.0 * e.error.max / target.diameter;
    return e;
  };

  // Pattern search (Hooke and Jeeves without the pattern move): try each parameter up and down
  // by its step, keep any improvement, halve the steps when none helps.
  DensityParameters best_d = r.start;
  Evaluation best;
  bool best_converged = false;
  int n = 0;
  auto record = [&](const DensityParameters& d, Evaluation&& e, double seconds) {
    DesignIteration it;
    it.index = n++;
    it.parameters = d;
    it.rms_error = e.rms;
    it.max_error = e.max;
    it.resin_share = e.stencil.resin_share;
    it.pieces = e.stencil.pieces;
    it.seconds = seconds;
    it.note = e.note;
    // Only an equilibrium is a prediction: an unconverged state competes only while no
    // converged one exists.
    const bool converged = e.note.empty();
    it.best = (converged && (!best_converged || e.rms < best.rms)) ||
              (!converged && !best_converged && e.rms < best.rms);
    if (it.best) {
      best = std::move(e);
      best_d = d;
      best_converged = converged;
    }
    r.history.push_back(it);
    if (progress) progress(it);
    return it.best;
  };
  auto out_of_budget = [&] { return n >= spec.evaluations || clock.seconds() >= spec.budget; };
  // Buckled forms have many branches, and the start from mechanics may sit on a flat one (a
  // sheet in tension stays flat): a few plain starts are tried too, and the search goes on from
  // the best of them.
  std::vector<DensityParameters> starts = {r.start};
  for (double mean : {r.start.mean, r.start.mean - 0.25, r.start.mean + 0.25}) {
    DensityParameters d;
    d.mean = std::clamp(mean, 0.0, 1.0);
    d.radial = d.anisotropy = 0.0;
    if (std::none_of(starts.begin(), starts.end(), [&](const DensityParameters& o) {
          return o.mean == d.mean && o.radial == d.radial && o.anisotropy == d.anisotropy;
        }))
      starts.push_back(d);
  }
  for (const DensityParameters& d : starts) {
    if (n > 0 && out_of_budget()) break;
    const Stopwatch t;
    Evaluation e = evaluate(d);
    record(d, std::move(e), t.seconds());
  }
  std::array<double, 3> step = {0.15, 0.2, 0.2};
  constexpr double min_step = 0.02;
  while (!out_of_budget() && step[0] >= min_step) {
    bool improved = false;
    for (int c = 0; c < 3 && !out_of_budget(); ++c)
      for (double sign : {+1.0, -1.0}) {
        if (out_of_budget()) break;
        DensityParameters d = best_d;
        double& v = c == 0 ? d.mean : c == 1 ? d.radial : d.anisotropy;
        v += sign * step[static_cast<size_t>(c)];
        if (c == 0) v = std::clamp(v, 0.0, 1.0);
        const Stopwatch t;
        Evaluation e = evaluate(d);
        if (record(d, std::move(e), t.seconds())) {
          improved = true;
          break;
        }
      }
    if (!improved)
      for (double& s : step) s *= 0.5;
  }
  if (best.scene.is_null() || best.run.prepared.membrane.state.x.cols() == 0)
    throw InputError(spec.file.string(), "no stencil could be simulated: " +
                                             (r.history.empty() ? std::string("no evaluation")
                                                                : r.history.back().note));
  if (!best_converged)
    r.message += std::string(r.message.empty() ? "" : " ") +
                 "No simulation reached equilibrium: the form shown is the last state of the "
                 "best one, not a prediction (more iterations, or the static solver).";
  r.best = best_d;
  r.scene = std::move(best.scene);
  r.stencil = std::move(best.stencil);
  r.run = std::move(best.run);
  r.error = std::move(best.error);
  r.rms_error = best.rms;
  r.max_error = best.max;
  r.seconds = clock.seconds();
  return r;
}

}  // namespace membra
