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
  std::vector<StencilSquare> squares;
  double total = 0.0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Vec2 centre = frame.min + Vec2((i + 0.5) * cx, (j + 0.5) * cy);
      if (inside && !inside(centre)) continue;
      total += cx * cy;
      const double rho = std::clamp(density(centre), 0.0, 1.0);
      // A square of the cell's shape with area share rho; too small a piece is dropped, too
      // narrow a gap closed.
      double scale = std::sqrt(rho);
      const double fx = scale * cx, fy = scale * cy;
      if (std::min(fx, fy) < w) continue;
      if (cx - fx < w || cy - fy < w) scale = 1.0;
      squares.push_back({centre, Vec2(cx, cy), scale});
    }
  return stencil_of(squares, total);
}

int Stencil::pieces_bottom() const {
  return static_cast<int>(std::count_if(squares.begin(), squares.end(),
                                        [](const StencilSquare& q) { return q.face < 0; })) +
         (pattern_bottom ? 1 : 0);
}

Stencil stencil_of(const std::vector<StencilSquare>& squares, double outline_area) {
  std::vector<std::array<Vec2, 4>> corners;
  double resin = 0.0;
  for (const StencilSquare& q : squares) {
    const Vec2 h = 0.5 * q.scale * q.cell;
    const Vec2& c = q.centre;
    std::array<Vec2, 4> square = {c - h, Vec2(c.x() + h.x(), c.y() - h.y()), c + h,
                                  Vec2(c.x() - h.x(), c.y() + h.y())};
    // Through mm, as a scene file holds it, so that the stencil simulated is the one written.
    for (Vec2& p : square) p = (p / units::mm) * units::mm;
    corners.push_back(square);
    resin += (q.scale * q.cell.x()) * (q.scale * q.cell.y());
  }
  Stencil out = stencil_of(corners);
  out.resin_share = outline_area > 0.0 ? resin / outline_area : 0.0;
  out.squares = squares;
  out.outline_area = outline_area;
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
