#include "membra/process/scene.hpp"

#include <functional>

#include "membra/model/continuum_sheet.hpp"

namespace membra {

namespace {

// The union of the patterns of the impregnate steps `keep` accepts (nullptr if none).
PatternPtr union_of_steps(const Scene& scene,
                          const std::function<bool(const ImpregnateStep&)>& keep) {
  std::vector<PatternPtr> parts;
  for (const auto& step : scene.protocol)
    if (const auto* i = step.as<ImpregnateStep>(); i && keep(*i)) parts.push_back(i->pattern);
  return parts.empty() ? nullptr : make_union(std::move(parts));
}

}  // namespace

const char* to_string(SheetModel model) {
  return model == SheetModel::continuum ? "continuum" : "lattice";
}

const char* to_string(Support support) {
  return support == Support::table ? "table" : "none";
}

double scene_max_edge(const Scene& scene) {
  return scene.mesh.max_edge > 0.0 ? scene.mesh.max_edge
                                   : default_max_edge(scene.grid.width, scene.grid.height);
}

PatternPtr scene_pattern(const Scene& scene) {
  return union_of_steps(scene, [](const ImpregnateStep&) { return true; });
}

PatternPtr scene_pattern(const Scene& scene, bool underside) {
  return union_of_steps(
      scene, [&](const ImpregnateStep& i) { return (i.bilayer && i.resin_side < 0) == underside; });
}

Box2 scene_frame(const Scene& scene) {
  Vec2 stretch(1.0, 1.0);
  for (const auto& step : scene.protocol)
    if (const auto* st = step.as<StretchStep>()) stretch = stretch.cwiseProduct(st->lambda);
  return {Vec2::Zero(), Vec2(stretch.x() * scene.grid.width, stretch.y() * scene.grid.height)};
}

}  // namespace membra
