#include "membra/process/steps.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "membra/core/input_error.hpp"
#include "membra/model/curvature_map.hpp"
#include "membra/model/cut.hpp"
#include "membra/model/grow.hpp"
#include "membra/model/partial_cover.hpp"

namespace membra {
namespace {

// A path that applies a growth gradually: at t, the share t of it in all.
Path growth_path(Membrane& m, GrowthPlan plan, int increments) {
  // The share applied so far lives in the path, so that a copy of the path (the viewer's undo)
  // carries its own.
  return {Path::Kind::gradual, increments,
          [&m, plan = std::move(plan), applied = 0.0](double t) mutable {
            apply_growth(m, plan, t - applied);
            applied = t;
          }};
}

// The path's symmetry-breaking imperfection, before its first increment.
void perturb_path(Membrane& m, const PathSettings& path) {
  if (path.random_imperfection)
    perturb_randomly(m, path.perturbation, path.seed);
  else
    perturb(m, path.perturbation, path.seed);
}

Path at_once() {
  Path p;
  p.kind = Path::Kind::at_once;
  return p;
}

Path nothing_to_solve() {
  return Path{};
}

}  // namespace

Path apply_stretch(Membrane& m, const StretchStep& step, StepEffects&) {
  stretch_frame(m, step.lambda.x(), step.lambda.y(), step.hold);
  return at_once();
}

Path apply_impregnate(Membrane& m, const ImpregnateStep& step, const std::string& pointer,
                      StepEffects& out) {
  out.report.resin_springs = impregnate(m, step.pattern, step.resin, step.resin_side, step.bilayer);
  if (out.report.resin_springs == 0)
    throw InputError(pointer + "/pattern",
                     "the pattern covers no spring of the sheet (is it between grid nodes, or "
                     "outside the stretched sheet?)");
  // On the continuum each triangle takes the material at its centroid: one the outline crosses
  // would be resin or latex throughout. The mesh follows the pattern, so none should: its
  // outlines were sampled on this frame to the chord tolerance and thinned to it again.
  if (m.sheet.continuum())
    out.report.partly_covered =
        triangles_across(m.sheet, m.state.x, *step.pattern, 2.0 * m.sheet.mesh.spec.tolerance);
  return nothing_to_solve();
}

Path apply_release(Membrane& m, const ReleaseStep& step, StepEffects&) {
  // The latex returns to its natural length along the path (time stepping: at once, from the
  // stretched state, as the paper's tool does).
  perturb_path(m, step.path);
  begin_release(m);
  return {Path::Kind::gradual, step.path.increments,
          [&m](double t) { set_release_level(m, 1.0 - t); }};
}

Path apply_grow(Membrane& m, const GrowStep& step, const std::string& pointer, StepEffects&) {
  GrowthPlan plan;
  try {
    plan = plan_growth(m.sheet.model, PatternGrowth(step.grow));
  } catch (const std::invalid_argument& e) {
    throw InputError(pointer + "/factor", e.what());
  }
  perturb_path(m, step.path);
  return growth_path(m, std::move(plan), step.path.increments);
}

Path apply_curvature_map(Membrane& m, const CurvatureMapStep& step, const std::string& pointer,
                         StepEffects& out) {
  const Model& model = m.sheet.model;
  std::vector<double> target(static_cast<size_t>(model.num_particles()));
  for (int q = 0; q < model.num_particles(); ++q) {
    const Vec2 at = model.reference.col(q).head<2>();
    try {
      target[q] = step.curvature(at);
    } catch (const std::invalid_argument& e) {
      throw InputError(pointer + "/K", e.what());
    }
    // The scene was checked on a grid; a continuum sheet's vertices lie between its nodes.
    if (!std::isfinite(target[q]))
      throw InputError(pointer + "/K", "K is not finite at (" + std::to_string(at.x() * 1e3) +
                                           ", " + std::to_string(at.y() * 1e3) +
                                           ") mm; it must be a finite number (1/mm^2) everywhere");
  }
  const ConformalFactor cf = conformal_factor(m.sheet, target);
  CurvatureMapResult cm;
  cm.step = pointer;
  cm.reached = cf.reached;
  cm.message = cf.message;
  out.curvature_map = cm;
  GrowthPlan plan = plan_growth(model, ConformalGrowth(cf.u));
  perturb_path(m, step.path);
  return growth_path(m, std::move(plan), step.path.increments);
}

Path apply_add_springs(Membrane& m, const AddSpringsStep& step, const std::string& pointer,
                       StepEffects& out) {
  AddSpringsSpec spec = step.add;
  const Material& latex = m.sheet.material;
  // On a mesh, springs of (sqrt 3 / 2) E t along every edge make a network as stiff in plane as
  // the latex sheet whatever the edges' length (a triangular network's modulus is 2k / sqrt 3).
  if (spec.stiffness <= 0.0)
    spec.stiffness = m.sheet.continuum()
                         ? 0.5 * std::sqrt(3.0) * latex.youngs_modulus * latex.thickness
                         : m.sheet.stiffness.stretch;
  Model& model = m.sheet.model;
  const int first = model.added_springs.size();
  out.report.springs_added =
      m.sheet.continuum() ? model.added_springs.add_along_edges(m.sheet.triangles, m.state.x, spec)
                          : model.added_springs.add_beside(model.springs, m.state.x, spec);
  if (out.report.springs_added == 0)
    throw InputError(pointer + "/pattern",
                     "the region covers no spring of the sheet (is it between grid nodes, or "
                     "outside the sheet?)");
  perturb_path(m, step.path);
  return {Path::Kind::gradual, step.path.increments,
          [&m, first, factor = spec.rest_factor](double t) {
            m.sheet.model.added_springs.set_level(first, factor, t);
          }};
}

Path apply_cut(Membrane& m, const CutStep& step, const std::string& pointer, StepEffects& out) {
  if (!step.line.empty()) {
    StressFeature f{pointer + "/line", "cut", {}};
    out.report.springs_cut = cut_along(m, step.line, &f.where);
    if (out.report.springs_cut == 0)
      throw InputError(pointer + "/line", "the cut crosses no spring of the sheet");
    out.features.push_back(std::move(f));
  }
  if (step.hole) {
    StressFeature f{pointer + "/hole", "hole", {}};
    try {
      out.report.particles_removed = punch_hole(m, *step.hole, &f.where);
    } catch (const std::invalid_argument& e) {
      throw InputError(pointer + "/hole", e.what());
    }
    if (out.report.particles_removed == 0)
      throw InputError(pointer + "/hole", "the hole covers no particle of the sheet");
    out.features.push_back(std::move(f));
  }
  return at_once();
}

Path apply_load(PreparedScene& p, const LoadStep& step, const std::string& pointer, StepEffects&) {
  if (step.gravity) p.membrane.sheet.model.gravity = Vec3(0.0, 0.0, -*step.gravity);
  p.pinned += pin(step.pins, pointer + "/pins", p);
  return at_once();
}

Path apply_step(PreparedScene& p, const ProtocolStep& step, StepEffects& out) {
  out.report.name = step_name(step.kind());
  out.report.pointer = step.pointer;
  Membrane& m = p.membrane;
  const std::string& at = step.pointer;
  return std::visit(
      [&](const auto& s) -> Path {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, StretchStep>) return apply_stretch(m, s, out);
        if constexpr (std::is_same_v<T, ImpregnateStep>) return apply_impregnate(m, s, at, out);
        if constexpr (std::is_same_v<T, ReleaseStep>) return apply_release(m, s, out);
        if constexpr (std::is_same_v<T, LoadStep>) return apply_load(p, s, at, out);
        if constexpr (std::is_same_v<T, GrowStep>) return apply_grow(m, s, at, out);
        if constexpr (std::is_same_v<T, AddSpringsStep>) return apply_add_springs(m, s, at, out);
        if constexpr (std::is_same_v<T, CutStep>) return apply_cut(m, s, at, out);
        if constexpr (std::is_same_v<T, CurvatureMapStep>)
          return apply_curvature_map(m, s, at, out);
      },
      step.step);
}

}  // namespace membra
