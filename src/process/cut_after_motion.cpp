#include "membra/process/cut_after_motion.hpp"

#include <stdexcept>
#include <string>
#include <utility>

#include "membra/core/input_error.hpp"
#include "membra/geometry/mesh_prolongation.hpp"
#include "membra/model/pattern_boundary.hpp"
#include "membra/model/top_view.hpp"
#include "membra/process/steps.hpp"

namespace membra {
namespace {

double signed_area(const std::vector<Vec2>& poly) {
  double a = 0.0;
  for (size_t k = 0; k < poly.size(); ++k) {
    const Vec2& p = poly[k];
    const Vec2& q = poly[(k + 1) % poly.size()];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * a;
}

std::vector<Vec2> on_frame(std::vector<Vec2> paper, const Vec2& stretch) {
  for (Vec2& p : paper) p = p.cwiseProduct(stretch);
  return paper;
}

// The hole's outlines where the sheet lies, pulled back: the outer ones joined, the inner ones
// (islands the hole leaves) taken out, as polygon patterns at paper points times the stretch.
PatternSpec hole_on_paper(const TopView& view, const Membrane& m, const Pattern& hole,
                          double spacing, double tolerance) {
  const Vec2 margin = Vec2::Constant(spacing);
  BoundaryOptions o;
  o.tolerance = tolerance;
  std::vector<PatternSpec> outer, inner;
  for (const Polygon2& poly :
       pattern_boundaries(hole, {view.lo() - margin, view.hi() + margin}, o)) {
    PatternSpec spec;
    spec.kind = PatternSpec::Kind::polygon;
    spec.points = on_frame(pull_back_polygon(view, poly, spacing), m.stretch);
    (signed_area(poly) >= 0.0 ? outer : inner).push_back(std::move(spec));
  }
  if (outer.empty())
    throw std::invalid_argument("the hole covers no part of the sheet as it lies now" +
                                view.extent());
  PatternSpec joined = union_spec(std::move(outer));
  if (inner.empty()) return joined;
  return difference_spec({std::move(joined), union_spec(std::move(inner))});
}

}  // namespace

SheetForm form_of(const Membrane& m) {
  return {m.sheet.model.reference, m.sheet.triangles, m.state.x};
}

bool moved_before(const Scene& scene, size_t index) {
  for (size_t k = 0; k < index && k < scene.protocol.size(); ++k) {
    const ProtocolStep& s = scene.protocol[k];
    const auto kind = s.kind();
    const auto* load = s.as<LoadStep>();
    if (kind == ProtocolStep::Kind::release || kind == ProtocolStep::Kind::grow ||
        kind == ProtocolStep::Kind::curvature_map ||
        (load && load->gravity && *load->gravity != 0.0))
      return true;
  }
  return false;
}

bool cut_remeshes(const Scene& scene, size_t index) {
  if (scene.model != SheetModel::continuum || index >= scene.protocol.size()) return false;
  const auto* cut = scene.protocol[index].as<CutStep>();
  return cut && !cut->on_paper && moved_before(scene, index);
}

bool any_cut_remeshes(const Scene& scene) {
  for (size_t k = 0; k < scene.protocol.size(); ++k)
    if (cut_remeshes(scene, k)) return true;
  return false;
}

ProtocolStep cut_on_paper(const Membrane& m, const ProtocolStep& step, double spacing) {
  ProtocolStep out = step;
  CutStep& cut = std::get<CutStep>(out.step);
  const TopView view(m);
  if (!cut.line.empty()) {
    try {
      cut.line = on_frame(pull_back_line(view, cut.line, spacing), m.stretch);
    } catch (const std::invalid_argument& e) {
      throw InputError(step.pointer + "/line", e.what());
    }
  }
  if (cut.hole) {
    try {
      cut.hole_spec = hole_on_paper(view, m, *cut.hole, spacing, 2e-5);
    } catch (const std::invalid_argument& e) {
      throw InputError(step.pointer + "/hole", e.what());
    }
    cut.hole = make_pattern(*cut.hole_spec, Vec2::Ones());
  }
  cut.on_paper = true;
  return out;
}

PreparedScene remesh_for_cut(const Scene& scene, size_t cut_index,
                             const std::vector<SheetForm>& forms, const SheetForm& now) {
  if (forms.size() != cut_index) throw std::logic_error("remesh_for_cut: a form per earlier step");
  PreparedScene p = prepare_scene(scene);
  Membrane& m = p.membrane;
  const auto carry = [&m](const SheetForm& f) {
    m.state.x = prolongate_on_mesh(f.reference, f.triangles, f.x, m.sheet.model.reference,
                                   m.sheet.triangles);
    m.state.v.setZero();
  };
  for (size_t k = 0; k < cut_index; ++k) {
    carry(forms[k]);
    StepEffects ignored;  // reported when the step was first taken
    const Path path = apply_step(p, scene.protocol[k], ignored);
    if (path.kind == Path::Kind::gradual) path.set(1.0);
  }
  carry(now);
  return p;
}

}  // namespace membra
