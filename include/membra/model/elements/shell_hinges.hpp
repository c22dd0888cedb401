#pragma once
// Shell hinges: the continuum sheet's bending, the discrete shells of Grinspun, Hirani, Desbrun
// and Schröder (2003, "Discrete Shells", SCA). A hinge is the pair of triangles (x0, x1, x2) and
// (x1, x0, x3) across the interior edge x0-x1; it stores k (theta - theta0)^2, theta the signed
// dihedral angle (hinge_kernel.hpp) and theta0 its rest angle (0 for a flat sheet; a bilayer's
// natural curvature later). k = (D/2) |e|^2 / A_e with A_e the two triangles' rest area, which
// sums to the plate energy (D/2) kappa^2 over the area on a bent cylinder (the constant is
// calibrated by the test on near-equilateral meshes; docs/model.md). D = E t^3 / (12 (1 - nu^2))
// of each side's material: the two halves bend in series, so across a resin edge the softer side
// takes the curvature, as the lattice's bending composite.
#include <array>
#include <string_view>
#include <vector>

#include "membra/model/elements/element_set.hpp"
#include "membra/model/elements/set_context.hpp"

namespace membra {

struct ShellHinges {
  static constexpr int kArity = 4;
  static constexpr std::string_view kName = "shell_hinges";
  static constexpr EnergyKind kEnergy = EnergyKind::bending;

  std::vector<std::array<int, 4>> v;  // x0, x1 (the shared edge), x2 (left), x3 (right)
  std::vector<double> stiffness;      // k, J per rad^2 (what the kernel reads)
  std::vector<double> rest_angle;     // theta0, rad
  // Material state: each side's rest area and plate stiffness D (N m), and |e|^2 at rest.
  std::vector<std::array<double, 2>> side_area, side_d;
  std::vector<std::array<bool, 2>> side_resin;  // a side has taken the resin's plate
  std::vector<double> edge_squared;

  int size() const { return static_cast<int>(v.size()); }
  std::array<int, 4> ids(int i) const { return v[static_cast<size_t>(i)]; }
  bool active(int i) const { return stiffness[static_cast<size_t>(i)] != 0.0; }
  // Appends a hinge across the edge p0-p1 of the natural sheet (p2 left of it, p3 right), both
  // sides of plate stiffness d (N m). Throws std::invalid_argument for a degenerate side.
  void add(const std::array<int, 4>& ids, const std::array<Vec3, 4>& p, double d);
  // Adds a hinge on every interior edge of a mesh of counter-clockwise triangles (rest positions
  // `reference`), plate stiffness d; returns how many.
  int add_mesh(const std::vector<std::array<int, 3>>& triangles, const Points& reference, double d);
  void filter(const std::vector<bool>& keep);
  // k from the two sides in series: 1/D_e = (A1/D1 + A2/D2) / (A1 + A2), k = (D_e/2)|e|^2/A_e.
  void update_stiffness(int i);

  // Kernel.
  double energy(int i, const Points& x) const;
  void add_forces(const Points& x, const Points* v, int begin, int end, Points& f) const;
  Eigen::Matrix<double, 12, 12> hessian(int i, const Points& x, bool project) const;
  void add_stiffness_estimate(const Points& x, std::vector<double>& diag) const;
  ElementStress stress(int, const Points&, double) const { return {}; }  // no in-plane stress

  // The stiffness does not follow the release; a flat sheet keeps theta0 = 0.
  void update(const ReleaseLevel&) {}
  void begin_release(const Points&) {}
  // Resin rule: a side whose triangle's centroid lies inside the pattern takes the plate of latex
  // and resin together, once (a later pattern over it adds nothing) (D of E_latex t_latex^3 +
  // E_resin t_resin^3, over 12 (1 - nu^2)), as the membrane triangles take their resin layer.
  int impregnate(const Impregnation& at);
  bool severed(int i, const CrossesCut& crosses) const;
  void carry(const ShellHinges& old, const Rebuild& r);
  ResinFootprint footprint(int, const Points&) const { return {}; }
  void set_resin_fraction(int, double, const ReleaseLevel&) {}
  double resin_rate(int, const Points&, const Points&, const ReleaseLevel&) const { return 0.0; }
};

}  // namespace membra
