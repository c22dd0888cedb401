#pragma once
// Bending of the sheet: an element (see bend_kernel.hpp) at every node along each of the four
// grid directions (x, y and both diagonals). With stiffness c = D/3 along the axes and D/6 along
// the diagonals, the elements store (D/2)(k1^2 + k2^2 + 2 nu k1 k2) per unit area with nu = 1/3 -
// the isotropic plate energy, with the same Poisson ratio as the spring lattice
// (derivation in docs/model.md). The set owns its latex and resin stiffness and the composite
// rule that mixes them by the share of the element inside resin.
#include <algorithm>
#include <array>
#include <string_view>
#include <vector>

#include "membra/model/elements/element_set.hpp"
#include "membra/model/elements/set_context.hpp"

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
  static constexpr int kArity = 3;
  static constexpr std::string_view kName = "bending";
  static constexpr EnergyKind kEnergy = EnergyKind::bending;

  std::vector<std::array<int, 3>> v;  // x0, x1 (the node), x2
  std::vector<double> stiffness;      // c, J (energy c psi^2 for small turning angles psi)
  std::vector<double> factor;         // c / D of this element (plate_bending_weights x its area)
  // Material state.
  std::vector<double> latex_stiffness;  // c of the latex alone, J
  std::vector<double> resin_stiffness;  // c of the resin alone, J
  std::vector<double> resin_fraction;   // share inside resin

  int size() const { return static_cast<int>(v.size()); }
  std::array<int, 3> ids(int i) const { return v[static_cast<size_t>(i)]; }
  bool active(int) const { return true; }
  // Appends an element of bare latex.
  void add(int a, int b, int c, double stiffness_, double factor_);
  void filter(const std::vector<bool>& keep);
  // Takes the current stiffnesses as the bare latex's (a new membrane).
  void reset_material();

  // Kernel.
  double energy(int i, const Points& x) const;
  void add_forces(const Points& x, const Points* v, int begin, int end, Points& f) const;
  Eigen::Matrix<double, 9, 9> hessian(int i, const Points& x, bool project) const;
  void add_stiffness_estimate(const Points& x, std::vector<double>& diag) const;
  // No in-plane stress.
  ElementStress stress(int, const Points&, double) const { return {}; }

  // Composite rule: latex and the latex-resin plate in series along the element, by the share
  // inside resin. The stiffness does not follow the release.
  static double composite(double latex, double resin, double fraction);
  void update(const ReleaseLevel&) {}
  void begin_release(const Points&) {}
  // Sets element e's resin share and its stiffness from the rule.
  void set_fraction(int e, double fraction);
  // dc/df at the element's current state (the design's sensitivities), J.
  double rate(int e) const;
  // The design's view: the element's two halves (its node is where a density is read), its
  // fraction set, and d/df of (grad E . w) (the energy is linear in c).
  ResinFootprint footprint(int e, const Points& x) const;
  void set_resin_fraction(int e, double f, const ReleaseLevel&) { set_fraction(e, f); }
  double resin_rate(int e, const Points& x, const Points& w, const ReleaseLevel&) const;
  // Resin rule: elements inside the pattern take the resin plate (formed in the stretched cells).
  int impregnate(const Impregnation& at);
  // Cut rule: an element goes when the cut crosses either of its segments.
  bool severed(int i, const CrossesCut& crosses) const {
    return crosses(v[i][0], v[i][1]) || crosses(v[i][1], v[i][2]);
  }
  // The old sheet's elements that still exist on the rebuilt one, with their resin; the others go.
  void carry(const Bending& old, const Rebuild& r);
  // Growth rule: none. The lattice's growth changes lengths (the springs'); the turning angles
  // keep their rest state, as in the paper's model.
  std::vector<LocalGrowth> growth(const GrowthField&, const Points&) const { return {}; }
  void grow(const std::vector<LocalGrowth>&, const Points&, double, const ReleaseLevel&) {}
};

}  // namespace membra
