#include "membra/design/stencil_layout.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "membra/core/units.hpp"

namespace membra {

Stencil layout_stencil(const std::function<double(const Vec2&)>& density, const Box2& frame,
                       const StencilLayout& layout,
                       const std::function<bool(const Vec2&)>& inside) {
  const double c = layout.cell, w = layout.min_feature;
  if (!(w > 0.0) || !(c >= 2.0 * w))
    throw std::invalid_argument("the cell must be at least twice the minimum feature width");
  const Vec2 size = frame.max - frame.min;
  const int nx = std::max(1, static_cast<int>(std::lround(size.x() / c)));
  const int ny = std::max(1, static_cast<int>(std::lround(size.y() / c)));
  const double cx = size.x() / nx, cy = size.y() / ny;  // cells fill the frame exactly
  Stencil s;
  std::vector<std::array<Vec2, 4>> squares;
  double resin = 0.0, total = 0.0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Vec2 centre = frame.min + Vec2((i + 0.5) * cx, (j + 0.5) * cy);
      if (inside && !inside(centre)) continue;
      total += cx * cy;
      const double rho = std::clamp(density(centre), 0.0, 1.0);
      // A square of the cell's shape with area share rho; too small a piece is dropped, too
      // narrow a gap closed.
      double fx = std::sqrt(rho) * cx, fy = std::sqrt(rho) * cy;
      if (std::min(fx, fy) < w) continue;
      if (cx - fx < w || cy - fy < w) fx = cx, fy = cy;
      const Vec2 h(0.5 * fx, 0.5 * fy);
      std::array<Vec2, 4> square = {centre - h, Vec2(centre.x() + h.x(), centre.y() - h.y()),
                                    centre + h, Vec2(centre.x() - h.x(), centre.y() + h.y())};
      // Through mm, as a scene file holds it, so that the stencil simulated is the one written.
      for (Vec2& p : square) p = (p / units::mm) * units::mm;
      squares.push_back(square);
      resin += fx * fy;
      ++s.pieces;
    }
  Stencil out = stencil_of(squares);
  out.resin_share = total > 0.0 ? resin / total : 0.0;
  out.pieces = s.pieces;
  return out;
}

Stencil stencil_of(const std::vector<std::array<Vec2, 4>>& squares) {
  Stencil s;
  s.pieces = static_cast<int>(squares.size());
  if (squares.empty()) return s;
  std::vector<PatternSpec> parts;
  for (const auto& square : squares) {
    PatternSpec p;
    p.kind = PatternSpec::Kind::polygon;
    p.points.assign(square.begin(), square.end());
    parts.push_back(std::move(p));
  }
  s.spec = parts.size() == 1 ? parts[0] : union_spec(std::move(parts));
  s.pattern = make_pattern(s.spec, Vec2::Zero());
  return s;
}

}  // namespace membra
