#pragma once
// Bilayer hinges: where resin soaks one face of the latex, the release leaves the two layers
// with different natural lengths and the composite curls with the resin on the convex side (a
// bimetal strip). A hinge is the pair of triangles (x0, x1, x2) and (x1, x0, x3) that share
// the edge x0-x1; it stores energy  moment * theta,  theta the signed dihedral angle across the
// edge (hinge_kernel.hpp). That is the linear part of the plate energy with a spontaneous
// curvature, (D/2)|k - k0|^2 = (D/2)|k|^2 - D k0 : k + const; the quadratic part is the
// ordinary bending elements'. docs/process.md derives the moments from k0.
#include <array>
#include <vector>

namespace membra {

struct Hinges {
  std::vector<std::array<int, 4>> v;  // x0, x1 (the shared edge), x2 (left), x3 (right)
  std::vector<double> moment;         // J per radian of dihedral angle; sign chooses the side

  int size() const { return static_cast<int>(v.size()); }
  bool empty() const { return v.empty(); }
  void add(const std::array<int, 4>& h, double m) {
    v.push_back(h);
    moment.push_back(m);
  }
};

}  // namespace membra
