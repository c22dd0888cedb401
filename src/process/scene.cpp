#include "membra/process/scene.hpp"

namespace membra {

PatternPtr scene_pattern(const Scene& scene) {
  std::vector<PatternPtr> parts;
  for (const auto& step : scene.protocol)
    if (const auto* i = step.as<ImpregnateStep>()) parts.push_back(i->pattern);
  if (parts.empty()) return nullptr;
  return parts.size() == 1 ? parts[0] : make_union(parts);
}

PatternPtr scene_pattern(const Scene& scene, bool underside) {
  std::vector<PatternPtr> parts;
  for (const auto& step : scene.protocol)
    if (const auto* i = step.as<ImpregnateStep>();
        i && (i->bilayer && i->resin_side < 0) == underside)
      parts.push_back(i->pattern);
  if (parts.empty()) return nullptr;
  return parts.size() == 1 ? parts[0] : make_union(parts);
}

Box2 scene_frame(const Scene& scene) {
  Vec2 stretch(1.0, 1.0);
  for (const auto& step : scene.protocol)
    if (const auto* st = step.as<StretchStep>()) stretch = stretch.cwiseProduct(st->lambda);
  return {Vec2::Zero(), Vec2(stretch.x() * scene.grid.width, stretch.y() * scene.grid.height)};
}

}  // namespace membra
