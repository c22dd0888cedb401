#pragma once
// The 2-D view: the sheet seen from straight above in frame coordinates (where resin is painted
// and cuts are drawn), fitted into a viewport with a margin.
#include <Eigen/Core>

#include "membra/model/pattern.hpp"

namespace membra {

struct FlatView {
  Box2 box;                   // frame coordinates shown, m
  int width = 1, height = 1;  // viewport, pixels
  double margin = 24.0;       // pixels around the box

  // Pixels per metre (the same along x and y).
  double scale() const;
  // Frame coordinates to pixels (origin top-left) and back.
  Eigen::Vector2d to_pixel(const Vec2& p) const;
  Vec2 to_frame(double px, double py) const;
  // World (x, y, z ignored) to clip space, for drawing the sheet flat.
  Eigen::Matrix4d view_projection() const;
};

}  // namespace membra
