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

std::vector<Vec2> on_frame(std::vector<Vec2> paper, const Vec2& stretch) {
  for (Vec2& p : paper) p = p.cwiseProduct(stretch);
  return paper;
}

// Each polygon's depth: the number of the others holding one of its vertices.
std::vector<int> nesting(const std::vector<PatternPtr>& shapes,
                         const std::vector<Polygon2>& polys) {
  std::vector<int> depth(polys.size(), 0);
  for (size_t i = 0; i < polys.size(); ++i)
    for (size_t j = 0; j < polys.size(); ++j)
      if (i != j && shapes[j]->contains(polys[i].front())) ++depth[i];
  return depth;
}

// The hole's outlines where the sheet lies, pulled back, as the region they bound by the
// even-odd rule: each outline at an even depth minus the outlines directly inside it (so a ring
// around a disk keeps the disk), at paper points times the stretch.
PatternSpec hole_on_paper(const TopView& view, const Membrane& m, const Pattern& hole,
                          double spacing, double tolerance) {
  const Vec2 margin = Vec2::Constant(spacing);
  BoundaryOptions o;
  o.tolerance = tolerance;
  const std::vector<Polygon2> drawn =
      pattern_boundaries(hole, {view.lo() - margin, view.hi() + margin}, o);
  if (drawn.empty())
    throw std::invalid_argument("the hole covers no part of the sheet as it lies now" +
                                view.extent());
  std::vector<PatternPtr> shapes;  // each outline's inside, built once
  for (const Polygon2& poly : drawn) shapes.push_back(make_polygon(poly));
  const std::vector<int> depth = nesting(shapes, drawn);
  std::vector<PatternSpec> paper(drawn.size()), regions;
  for (size_t i = 0; i < drawn.size(); ++i)
    paper[i] = polygon_spec(on_frame(pull_back_polygon(view, drawn[i], spacing), m.stretch));
  for (size_t i = 0; i < drawn.size(); ++i) {
    if (depth[i] % 2 != 0) continue;
    std::vector<PatternSpec> parts{paper[i]};
    for (size_t j = 0; j < drawn.size(); ++j)
      if (depth[j] == depth[i] + 1 && shapes[i]->contains(drawn[j].front()))
        parts.push_back(paper[j]);
    regions.push_back(parts.size() == 1 ? parts[0] : difference_spec(std::move(parts)));
  }
  return regions.size() == 1 ? regions[0] : union_spec(std::move(regions));
}

}  // namespace

SheetForm form_of(const Membrane& m) {
  return {m.sheet.model.reference, m.sheet.triangles, m.state.x};
}

bool moves_sheet(const ProtocolStep& step) {
  const auto kind = step.kind();
  const auto* load = step.as<LoadStep>();
  return kind == ProtocolStep::Kind::release || kind == ProtocolStep::Kind::grow ||
         kind == ProtocolStep::Kind::curvature_map ||
         (load && load->gravity && *load->gravity != 0.0);
}

bool moved_before(const Scene& scene, size_t index) {
  for (size_t k = 0; k < index && k < scene.protocol.size(); ++k)
    if (moves_sheet(scene.protocol[k])) return true;
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

ProtocolStep cut_on_paper(const Membrane& m, const ProtocolStep& step, double spacing,
                          double tolerance) {
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
      cut.hole_spec = hole_on_paper(view, m, *cut.hole, spacing, tolerance);
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
