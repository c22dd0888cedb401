#pragma once
// Bending of the sheet: an element (see bend_kernel.hpp) at every node along each of the four
// grid directions (x, y and both diagonals). With stiffness c = D/3 along the axes and D/6 along
// the diagonals, the elements store (D/2)(k1^2 + k2^2 + 2 nu k1 k2) per unit area with nu = 1/3 -
// the isotropic plate energy, with the same Poisson ratio as the spring lattice
// (derivation in docs/model.md).
#include <array>
#include <vector>

namespace membra {

struct Bending {
  std::vector<std::array<int, 3>> v;  // x0, x1 (the node), x2
  std::vector<double> stiffness;      // c, J (energy c psi^2 for small turning angles psi)
  std::vector<double> factor;         // c / D of this element: 1/3 (axis) or 1/6 (diagonal)

  int size() const { return static_cast<int>(v.size()); }
  void add(int a, int b, int c, double stiffness_, double factor_) {
    v.push_back({a, b, c});
    stiffness.push_back(stiffness_);
    factor.push_back(factor_);
  }
};

}  // namespace membra
