#pragma once
// Self-contact of the continuum sheet (`simulation.self_contact`, docs/model.md, "Self-contact"):
// a point of the sheet may not pass through a triangle of the sheet. Each element is a pair, a
// particle and a triangle that does not hold it, whose energy is the barrier of
// self_contact_kernel.hpp: zero beyond the gap, unbounded as the particle reaches the triangle.
// Which pairs can touch depends on where the sheet is, so the pairs are gathered from the
// positions (`refresh`): every pair nearer than 1.5 gaps must be in the list, and a new list
// holds those nearer than 2 gaps. The list is a cache of the positions, like the shell's plans,
// so it is refreshed through a const set; a solver that refreshes it sets up its Hessian's
// pattern again. Between refreshes a solver keeps its steps short enough (`step_limit`) that no
// pair in the list reaches zero distance and none outside it comes within the gap: so a sheet
// that starts without crossings never passes through itself.
// Points that lie closer than `exclusion` on the natural sheet never form a pair: they are
// neighbours in the material, whose distance the membrane already holds.
#include <array>
#include <string_view>
#include <vector>

#include "membra/geometry/triangulation.hpp"
#include "membra/model/elements/element_set.hpp"
#include "membra/model/elements/self_contact_kernel.hpp"
#include "membra/model/elements/set_context.hpp"

namespace membra {

// How the sheet's self-contact stands at positions x, for the report.
struct ContactReading {
  int touching = 0;           // pairs nearer than the gap
  double min_distance = 0.0;  // m, the nearest pair's distance (the gap where none is listed)
  double push = 0.0;          // N, the sum of the barrier's forces on the touching particles
};

struct SelfContact : NoResinRule {
  static constexpr int kArity = 4;
  static constexpr std::string_view kName = "self_contact";
  static constexpr EnergyKind kEnergy = EnergyKind::contact;
  static constexpr double kDefaultGap = 1e-3;         // m
  static constexpr double kDefaultPressure = 1000.0;  // Pa
  // The longest step (in gaps) step_limit lets a particle take: bounds its broad phase.
  static constexpr double kMaxReach = 100.0;

  // The sheet's surface: triangles (particle ids), each particle's share of the natural area
  // (m^2) and the natural positions (m), and the barrier's gap (m), pressure scale (Pa) and
  // exclusion (m). Set by `cover`.
  std::vector<Triangle> triangle;
  std::vector<double> area;
  Points rest;
  double gap = kDefaultGap;
  double pressure = kDefaultPressure;
  double exclusion = 3.0 * kDefaultGap;

  // Covers the surface `triangles` of a sheet with natural positions `rest` (3 x N, m), with the
  // given gap (m, > 0), pressure scale (Pa, > 0) and exclusion (m, >= 2 gap): replaces what was
  // there and empties the pair list. Throws std::invalid_argument for values out of range.
  void cover(const std::vector<Triangle>& triangles, const Points& rest, double gap,
             double pressure, double exclusion);
  // The same gap, pressure and exclusion on a sheet whose particles or triangles changed (a
  // slit's new lips); nothing when self-contact is off.
  void recover(const std::vector<Triangle>& triangles, const Points& rest);
  bool enabled() const { return !triangle.empty(); }

  // Gathers the pairs again when a pair nearer than 1.5 gaps at x is not in the list; true when
  // the list changed (a solver's Hessian pattern then changes with it). Writes the cache: not
  // to be called from two threads on one set (each solve works on its own model).
  bool refresh(const Points& x) const;
  // The largest share alpha in [0, 1] of a step that moves particle p by at most
  // alpha |d_p - d_q| + alpha^2 |e_p - e_q| relative to any particle q (d: the step, e: its
  // curvature, or empty) such that no pair of the list comes nearer than a tenth of its distance
  // at x and no other pair comes within the gap (with the list refreshed at x); never more
  // than kMaxReach gaps of motion for any particle.
  double step_limit(const Points& x, const Points& d, const Points& e) const;
  ContactReading read(const Points& x) const;
  // The pairs another copy of this sheet gathered (a solve on a copy of the model).
  void take_pairs(const SelfContact& from) const { pairs_ = from.pairs_; }

  int size() const { return static_cast<int>(pairs_.size()); }
  std::array<int, 4> ids(int i) const { return pairs_[static_cast<size_t>(i)]; }
  bool active(int) const { return true; }
  void filter(const std::vector<bool>& keep);

  double energy(int i, const Points& x) const;
  void add_forces(const Points& x, const Points* v, int begin, int end, Points& f) const;
  ContactHessian hessian(int i, const Points& x, bool project) const;
  void add_stiffness_estimate(const Points& x, std::vector<double>& diag) const;
  ElementStress stress(int, const Points&, double) const { return {}; }

  std::vector<LocalGrowth> growth(const GrowthField&, const Points&) const { return {}; }
  void grow(const std::vector<LocalGrowth>&, const Points&, double, const ReleaseLevel&) {}
  bool severed(int, const CrossesCut&) const { return false; }
  // A rebuilt sheet (a hole, a cut): its surviving triangles, at its natural positions; the
  // pairs are gathered anew.
  void carry(const SelfContact& old, const Rebuild& r);

 private:
  // Every pair nearer than `radius` at x, not excluded, sorted.
  std::vector<std::array<int, 4>> near_pairs(const Points& x, double radius) const;
  double weight(int i) const;

  mutable std::vector<std::array<int, 4>> pairs_;  // particle, triangle's three particles
};

}  // namespace membra
