#include "membra/view/flat_view.hpp"

#include <algorithm>

namespace membra {

double FlatView::scale() const {
  const Vec2 size = (box.max - box.min).cwiseMax(Vec2::Constant(1e-12));
  return std::max(1e-12,
                  std::min((width - 2.0 * margin) / size.x(), (height - 2.0 * margin) / size.y()));
}

Eigen::Vector2d FlatView::to_pixel(const Vec2& p) const {
  const Vec2 c = 0.5 * (box.min + box.max);
  const double s = scale();
  return {0.5 * width + s * (p.x() - c.x()), 0.5 * height - s * (p.y() - c.y())};
}

Vec2 FlatView::to_frame(double px, double py) const {
  const Vec2 c = 0.5 * (box.min + box.max);
  const double s = scale();
  return {c.x() + (px - 0.5 * width) / s, c.y() - (py - 0.5 * height) / s};
}

Eigen::Matrix4d FlatView::view_projection() const {
  const Vec2 c = 0.5 * (box.min + box.max);
  const double sx = 2.0 * scale() / width, sy = 2.0 * scale() / height;
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = sx;
  m(0, 3) = -sx * c.x();
  m(1, 1) = sy;
  m(1, 3) = -sy * c.y();
  m(3, 3) = 1.0;  // z is dropped: the flat view draws in painter's order
  return m;
}

}  // namespace membra
