#pragma once
// Bilayer hinges: where resin soaks one face of the latex, the release leaves the two layers
// with different natural lengths and the composite curls with the resin on the convex side (a
// bimetal strip). A hinge is the pair of triangles (x0, x1, x2) and (x1, x0, x3) that share
// the edge x0-x1; it stores energy  moment * theta,  theta the signed dihedral angle across the
// edge (hinge_kernel.hpp). That is the linear part of the plate energy with a spontaneous
// curvature, (D/2)|k - k0|^2 = (D/2)|k|^2 - D k0 : k + const; the quadratic part is the
// ordinary bending elements'. docs/process.md derives the moments from k0.
#include <array>
#include <string_view>
#include <vector>

#include "membra/model/elements/element_set.hpp"
#include "membra/model/elements/set_context.hpp"

namespace membra {

struct Hinges {
  static constexpr int kArity = 4;
  static constexpr std::string_view kName = "hinges";
  static constexpr EnergyKind kEnergy = EnergyKind::bending;

  std::vector<std::array<int, 4>> v;  // x0, x1 (the shared edge), x2 (left), x3 (right)
  std::vector<double> moment;         // J per radian of dihedral angle; sign chooses the side
  // Material state.
  std::vector<double> full_moment;  // the moment once the release is complete, J/rad
  std::vector<double> coverage;     // the share of the hinge coated so far, at most 1

  int size() const { return static_cast<int>(v.size()); }
  bool empty() const { return v.empty(); }
  std::array<int, 4> ids(int i) const { return v[static_cast<size_t>(i)]; }
  // A hinge without a moment stores nothing (before the release, or outside every coat).
  bool active(int i) const { return moment[static_cast<size_t>(i)] != 0.0; }
  // Appends a hinge with moment m (and that full moment and coverage).
  void add(const std::array<int, 4>& h, double m, double full = 0.0, double covered = 0.0);
  void filter(const std::vector<bool>& keep);

  // Kernel.
  double energy(int i, const Points& x) const;
  void add_forces(const Points& x, const Points* v, int begin, int end, Points& f) const;
  Eigen::Matrix<double, 12, 12> hessian(int i, const Points& x, bool project) const;
  void add_stiffness_estimate(const Points&, std::vector<double>&) const {}  // no stiffness
  // No in-plane stress.
  ElementStress stress(int, const Points&, double) const { return {}; }

  // The moments for the release level: the full moment times the share of the misfit released
  // so far (none before the release).
  void update(const ReleaseLevel& release);
  void begin_release(const Points&) {}  // the moments follow the level alone
  // Resin rule, for a bilayer coat only: adds hinges inside the pattern whose moments make the
  // released composite curl with the resin on the coat's face. The misfit is the latex's current
  // stretch: eps = I - V^-1, V the in-plane stretch of the hinge's two triangles from the paper to
  // the frame. A hinge the pattern covers by a share f takes f of the spontaneous curvature
  // (bilayer.hpp) at the stiffness of coat and bare latex in series (so a coat's edge does not
  // crease); a hinge an earlier coat covers in part takes the rest from this one, up to the
  // whole. Returns the number of hinges with resin.
  int impregnate(const Impregnation& at);
  // The design places no resin on hinges (a coat is laid out as a stencil, not by the maps).
  ResinFootprint footprint(int, const Points&) const { return {}; }
  void set_resin_fraction(int, double, const ReleaseLevel&) {}
  double resin_rate(int, const Points&, const Points&, const ReleaseLevel&) const { return 0.0; }
  // Cut rule: a hinge goes with either of its triangles.
  bool severed(int i, const CrossesCut& crosses) const;
  // The old sheet's hinges whose four particles and two triangles survive, with their moments.
  void carry(const Hinges& old, const Rebuild& r);
  // Growth rule: none; a bilayer's moment is the resin's, which does not grow.
  std::vector<LocalGrowth> growth(const GrowthField&, const Points&) const { return {}; }
  void grow(const std::vector<LocalGrowth>&, const Points&, double, const ReleaseLevel&) {}
};

}  // namespace membra
