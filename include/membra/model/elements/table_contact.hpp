#pragma once
// The piece at rest on a table (`simulation.support: "table"`, docs/model.md, "On a table"): a
// frictionless plane z = height under every particle, as a one-sided penalty smooth enough for
// Newton. A particle a depth d below the plane stores w d^3 / (3 delta^2), w its weight (m g):
// under its own weight alone it rests `softness` (delta) below the plane, and its contact
// stiffness, 2 w d / delta^2, grows from zero as it presses, so energy, force and Hessian are
// continuous when a particle lands or lifts off (C2). The plane pushes along z only: no friction.
#include <array>
#include <string_view>
#include <vector>

#include "membra/model/elements/element_set.hpp"
#include "membra/model/elements/set_context.hpp"

namespace membra {

// What the table does at positions x: how many particles touch it, the deepest one's depth (m),
// and the sum of its push (N), which at equilibrium carries the piece's whole weight (N).
struct TableReading {
  int touching = 0;
  double max_depth = 0.0;
  double reaction = 0.0;
  double weight = 0.0;
};

struct TableContact : NoResinRule {
  static constexpr int kArity = 1;
  static constexpr std::string_view kName = "table";
  static constexpr EnergyKind kEnergy = EnergyKind::support;
  // A tenth of a millimetre: far below the forms' millimetres, soft enough to keep Newton's
  // systems as well conditioned as the latex's own (docs/model.md, "On a table").
  static constexpr double kDefaultSoftness = 1e-4;

  std::vector<int> particle;           // one element per particle it holds
  std::vector<double> weight;          // N, that particle's m g
  double height = 0.0;                 // m, the plane's z
  double softness = kDefaultSoftness;  // m, a particle's depth under its own weight alone
  double gravity = 9.81;               // m/s^2, the g the weights were taken at

  // Puts every particle of masses `mass` (kg) on a plane at `height` under gravity g (m/s^2,
  // > 0), with depth `softness` (m, > 0) under its own weight; replaces what was there. Throws
  // std::invalid_argument for a g or softness that is not positive and finite.
  void rest_on(const std::vector<double>& mass, double g, double height, double softness);

  // Every particle of masses `mass` on the same plane, when there is one (a sheet whose particles
  // or masses changed: a hole, a slit's new lips); nothing when the set is empty.
  void cover(const std::vector<double>& mass);

  int size() const { return static_cast<int>(particle.size()); }
  std::array<int, 1> ids(int i) const { return {particle[static_cast<size_t>(i)]}; }
  bool active(int) const { return true; }
  void filter(const std::vector<bool>& keep);

  // How far particle i lies below the plane (m, 0 when above it).
  double depth(int i, const Points& x) const;
  double energy(int i, const Points& x) const;
  void add_forces(const Points& x, const Points* v, int begin, int end, Points& f) const;
  Eigen::Matrix3d hessian(int i, const Points& x, bool project) const;
  // The stiffness of a particle pressed to its own weight's depth (2 w / delta), whether or not
  // it touches now: the static solver's time step must hold when it lands.
  void add_stiffness_estimate(const Points& x, std::vector<double>& diag) const;
  TableReading read(const Points& x) const;
  // The plane carries no stress of the sheet's.
  ElementStress stress(int, const Points&, double) const { return {}; }

  // No composite rule, no resin (NoResinRule), no growth: the table is not part of the sheet.
  std::vector<LocalGrowth> growth(const GrowthField&, const Points&) const { return {}; }
  void grow(const std::vector<LocalGrowth>&, const Points&, double, const ReleaseLevel&) {}
  // Cut rule: a cut severs no contact; a rebuilt sheet's surviving particles keep theirs.
  bool severed(int, const CrossesCut&) const { return false; }
  void carry(const TableContact& old, const Rebuild& r);
};

}  // namespace membra
