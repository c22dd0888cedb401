#pragma once
// Bending of the sheet: an element (see bend_kernel.hpp) at every node along each of the four
// grid directions (x, y and both diagonals). With stiffness c = D/3 along the axes and D/6 along
// the diagonals, the elements store (D/2)(k1^2 + k2^2 + 2 nu k1 k2) per unit area with nu = 1/3 -
// the isotropic plate energy, with the same Poisson ratio as the spring lattice
// (derivation in docs/model.md).
#include <algorithm>
#include <array>
#include <vector>

namespace membra {

// c / D of the elements of a node with a full neighbourhood on a grid of hx x hy cells. Matching
// (D/2)(kxx^2 + kyy^2 + 2 nu kxx kyy + 2 (1 - nu) kxy^2) term by term gives, for nu = 1/3 only
// (the lattice's), diagonals l^2 / (12 hx hy) and axes hy / (2 hx) - hx / (6 hy) (x) and
// hx / (2 hy) - hy / (6 hx) (y): 1/3 and 1/6 on square cells. An axis weight would turn
// negative beyond an aspect ratio of sqrt(3); it is held at 0 there (the sheet is then stiffer
// than the plate along that axis).
struct PlateWeights {
  double x = 1.0 / 3.0, y = 1.0 / 3.0, diagonal = 1.0 / 6.0;
};
inline PlateWeights plate_bending_weights(double hx, double hy) {
  PlateWeights w;
  w.x = std::max(0.0, hy / (2.0 * hx) - hx / (6.0 * hy));
  w.y = std::max(0.0, hx / (2.0 * hy) - hy / (6.0 * hx));
  w.diagonal = (hx * hx + hy * hy) / (12.0 * hx * hy);
  return w;
}

struct Bending {
  std::vector<std::array<int, 3>> v;  // x0, x1 (the node), x2
  std::vector<double> stiffness;      // c, J (energy c psi^2 for small turning angles psi)
  std::vector<double> factor;         // c / D of this element (plate_bending_weights x its area)

  int size() const { return static_cast<int>(v.size()); }
  void add(int a, int b, int c, double stiffness_, double factor_) {
    v.push_back({a, b, c});
    stiffness.push_back(stiffness_);
    factor.push_back(factor_);
  }
};

}  // namespace membra
