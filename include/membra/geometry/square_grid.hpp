#pragma once
// Nodes for a w x h rectangle with square cells (the lattice's homogenization is for square
// cells; docs/model.md).
#include <utility>

namespace membra {

// `n` nodes along the shorter side and as many square cells as fit along the other; where they
// do not fit within 1 % (an elongated sheet on a coarse grid: 86 x 155 mm at 9 nodes gives cells
// of 10.76 and 11.07 mm), the first finer grid whose cells do (there always is one by 51 nodes).
// Returns (nx, ny).
std::pair<int, int> square_grid(double w, double h, int n);

}  // namespace membra
