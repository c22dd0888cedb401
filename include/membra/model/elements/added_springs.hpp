#pragma once
// Springs added beside the lattice's (the paper's "adding accumulative amounts of springs to the
// mesh locally", the add_springs step): extra springs in a region of the sheet that keep the rest
// length they are given through every later step (the release does not touch them; a growth
// scales them as it scales the latex), so springs shorter than the sheet there pull it together
// and longer ones push it apart. Not part of the sheet: they take no resin, carry no stress of
// the sheet's, and the design places no resin on them.
#include <array>
#include <optional>
#include <string_view>
#include <vector>

#include "membra/geometry/triangulation.hpp"
#include "membra/model/elements/element_set.hpp"
#include "membra/model/elements/set_context.hpp"
#include "membra/model/elements/springs.hpp"
#include "membra/model/pattern.hpp"

namespace membra {

struct AddSpringsSpec {
  PatternPtr region;  // frame coordinates (where the sheet is now, seen from above)
  std::optional<SpringFamily> along = SpringFamily::stretch;  // beside which lattice springs
  int count = 1;             // springs beside each lattice spring (>= 1)
  double stiffness = 0.0;    // k of one added spring, N/m (> 0)
  double rest_factor = 1.0;  // rest length / current length (> 0)
};

struct AddedSprings : NoResinRule {
  static constexpr int kArity = 2;
  static constexpr std::string_view kName = "added springs";
  static constexpr EnergyKind kEnergy = EnergyKind::stretching;

  std::vector<int> a, b;             // particle indices
  std::vector<double> rest_length;   // m
  std::vector<double> stiffness;     // N/m
  std::vector<double> damping;       // N*s/m, on the relative velocity along the spring
  std::vector<double> start_length;  // m, the length when added (the add path's level 0)

  int size() const { return static_cast<int>(a.size()); }
  std::array<int, 2> ids(int i) const { return {a[i], b[i]}; }
  bool active(int) const { return true; }
  void filter(const std::vector<bool>& keep);

  // Adds the springs beside every lattice spring (of family `along`, any when empty) whose length
  // at positions x lies at least half inside the region, at rest at their current length.
  // `count` springs in parallel act as one of count x k, and are stored so. Returns the number
  // of springs added (count x pairs), 0 if the region covers none. Throws std::invalid_argument
  // for a spec without a region, a count below 1 or a stiffness or rest factor not positive.
  int add_beside(const Springs& lattice, const Points& x, const AddSpringsSpec& spec);
  // The continuum sheet's: one spring along every edge of the mesh `triangles` whose length at x
  // lies at least half inside the region (`along` is not read), as add_beside otherwise.
  int add_along_edges(const std::vector<Triangle>& triangles, const Points& x,
                      const AddSpringsSpec& spec);
  // Moves the rest lengths of the springs from `first` on from their start length (level 0) to
  // rest_factor x that length (level 1), for a gradual path.
  void set_level(int first, double rest_factor, double level);

  // Kernel (spring_kernel.hpp's, as the lattice's springs).
  double energy(int i, const Points& x) const;
  void add_forces(const Points& x, const Points* v, int begin, int end, Points& f) const;
  Eigen::Matrix<double, 6, 6> hessian(int i, const Points& x, bool project) const;
  void add_stiffness_estimate(const Points& x, std::vector<double>& diag) const;
  // Strain and force; no stress of the sheet's (no tributary width).
  ElementStress stress(int i, const Points& x, double thickness) const;

  // No composite rule, no resin (NoResinRule): they keep what they were given.

  // Growth rule: a growth of the "added" family, or of every element, scales their rest length
  // by its ratio along them, as the lattice's latex.
  std::vector<LocalGrowth> growth(const GrowthField& field, const Points& paper) const;
  void grow(const std::vector<LocalGrowth>& g, const Points& paper, double exponent,
            const ReleaseLevel& release);
  // Cut rule: a spring goes when the cut crosses it; those whose ends survive a rebuild come
  // along with their state.
  bool severed(int i, const CrossesCut& crosses) const { return crosses(a[i], b[i]); }
  void carry(const AddedSprings& old, const Rebuild& r);

 private:
  void push(int pa, int pb, double l0, double k, double c, double start);
};

}  // namespace membra
