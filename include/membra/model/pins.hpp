#pragma once
// Pinning particles of a sheet: corners, whole edges, the particle nearest a point, or a box.
#include <string>
#include <vector>

#include "membra/model/sheet.hpp"

namespace membra {

// Which particles to pin, in paper coordinates (m).
struct PinSpec {
  enum class Kind { corners, edge, point, box } kind = Kind::corners;
  std::string edge;                                     // left | right | bottom | top
  Vec2 point = Vec2::Zero();                            // Kind::point: nearest particle
  Vec2 box_min = Vec2::Zero(), box_max = Vec2::Zero();  // Kind::box: all particles inside
};

// Pins the particles each spec selects and returns how many were pinned in all. A spec that
// selects no particle (a box between nodes, a corner removed by a mask) throws
// std::invalid_argument naming the spec's index. On a continuum sheet (a grid without particles)
// corners and edges are found by paper position.
int apply_pins(const std::vector<PinSpec>& pins, const GridSheet& grid, Model& model);

}  // namespace membra
