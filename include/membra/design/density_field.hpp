#pragma once
// The fine design variables of inverse design: a resin density (0..1) per square cell of a grid
// over the frame, read anywhere by bilinear interpolation between the cell centres (constant
// beyond the outer centres). The interpolation is the design's filter, about one cell wide: the
// material a spring sees changes smoothly with the variables, so the released form does too and
// gradients exist (docs/inverse_design.md).
#include <array>

#include <Eigen/Core>

#include "membra/model/pattern.hpp"

namespace membra {

struct DensityField {
  Box2 frame;             // m, frame coordinates
  int nx = 1, ny = 1;     // cells along x and y
  Eigen::VectorXd value;  // per cell, index i + nx j, within [0, 1]

  // The cells whose centres surround p and their bilinear weights (summing to 1).
  struct Weights {
    std::array<int, 4> cell{};
    std::array<double, 4> weight{};
  };
  Weights weights(const Vec2& p) const;
  double at(const Vec2& p) const;
  Vec2 cell_size() const;
  Vec2 centre(int cell) const;
};

// A field of cells about `cell` wide (a whole number of them along each side of the frame), every
// cell at `value`. Throws std::invalid_argument for an empty frame or a cell not > 0.
DensityField make_density_field(const Box2& frame, double cell, double value);

}  // namespace membra
