#include "membra/design/design_stretch.hpp"

#include <variant>

#include "membra/geometry/square_grid.hpp"

namespace membra {

Vec2 stretched_lambda(const Vec2& lambda, double factor) {
  return Vec2::Ones() + factor * (lambda - Vec2::Ones());
}

DesignSpec with_stretch(const DesignSpec& spec, double factor) {
  if (factor == 1.0) return spec;
  DesignSpec s = spec;
  s.lambda = stretched_lambda(spec.lambda, factor);
  GridSpec& g = s.scene.grid;
  g.width = s.frame / s.lambda.x();
  g.height = s.frame / s.lambda.y();
  std::tie(g.nx, g.ny) = square_grid(g.width, g.height, s.resolution);
  for (ProtocolStep& step : s.scene.protocol)
    if (auto* stretch = std::get_if<StretchStep>(&step.step)) stretch->lambda = s.lambda;
  return s;
}

}  // namespace membra
