#pragma once
// Angle defects: the plate's Gaussian-curvature term on the continuum sheet (docs/model.md, "The
// continuum shell"). The shell hinges alone store (D/2)(4H^2 - (8/3)K) per unit area on smooth
// bends of near-equilateral meshes, where Kirchhoff's plate stores (D/2)(4H^2 - 2(1 - nu)K);
// this set adds the difference, (D/2) c K with c = 8/3 - 2(1 - nu), as discrete Gaussian
// curvature: w_v (2 pi - sum of angles) at each interior particle v, w_v = c D / 2 averaged over
// the particle's triangles by area. Per triangle that is the sum over its corners at interior
// particles of w_v (theta0 - theta), theta the corner angle now and theta0 on the flat natural
// sheet (a triangle's angles always sum to pi, so only corners of different weights, or on the
// rim, store anything). For a uniform plate the sum is a boundary term (Gauss-Bonnet): it acts at
// free edges and where the plate's stiffness changes, as the nu term of plate theory does.
#include <array>
#include <string_view>
#include <vector>

#include "membra/model/elements/element_set.hpp"
#include "membra/model/elements/set_context.hpp"

namespace membra {

// The coefficient c of the Gaussian-curvature correction for a plate of Poisson ratio nu.
inline double angle_defect_coefficient(double nu) {
  return 8.0 / 3.0 - 2.0 * (1.0 - nu);
}

struct AngleDefects {
  static constexpr int kArity = 3;
  static constexpr std::string_view kName = "angle_defects";
  static constexpr EnergyKind kEnergy = EnergyKind::bending;

  std::vector<std::array<int, 3>> v;          // the triangles, counter-clockwise
  std::vector<std::array<double, 3>> rest;    // theta0 of each corner, rad
  std::vector<std::array<double, 3>> weight;  // w_v of each corner's particle (0 on the rim), J
  // Material state: each triangle's c D (latex and resin each with its own nu's c, N m), its
  // rest area (m^2), whether it took the resin, and its corners' particles off the rim.
  std::vector<double> plate, area;
  std::vector<bool> resin;
  std::vector<std::array<bool, 3>> interior;

  int size() const { return static_cast<int>(v.size()); }
  std::array<int, 3> ids(int i) const { return v[static_cast<size_t>(i)]; }
  bool active(int i) const {
    const auto& w = weight[static_cast<size_t>(i)];
    return w[0] != 0.0 || w[1] != 0.0 || w[2] != 0.0;
  }
  // A term on every triangle of a mesh at rest at `reference`, c D = cd; corners at the
  // particles `on_rim` (sorted or not) take no part.
  void add_mesh(const std::vector<std::array<int, 3>>& triangles, const Points& reference,
                double cd, const std::vector<int>& on_rim);
  void filter(const std::vector<bool>& keep);
  // w_v of every particle from its triangles' c D, averaged by area (after the plates change).
  void update_weights();

  // Kernel.
  double energy(int i, const Points& x) const;
  void add_forces(const Points& x, const Points* v, int begin, int end, Points& f) const;
  Eigen::Matrix<double, 9, 9> hessian(int i, const Points& x, bool project) const;
  void add_stiffness_estimate(const Points& x, std::vector<double>& diag) const;
  ElementStress stress(int, const Points&, double) const { return {}; }

  void update(const ReleaseLevel&) {}
  void begin_release(const Points&) {}
  // Resin rule, as the shell hinges': a triangle whose centroid lies in the pattern adds the
  // resin's plate to its D (with the resin's c, nu 1/3), once; the weights follow.
  int impregnate(const Impregnation& at);
  bool severed(int i, const CrossesCut& crosses) const;
  void carry(const AngleDefects& old, const Rebuild& r);
  ResinFootprint footprint(int, const Points&) const { return {}; }
  void set_resin_fraction(int, double, const ReleaseLevel&) {}
  double resin_rate(int, const Points&, const Points&, const ReleaseLevel&) const { return 0.0; }
};

}  // namespace membra
