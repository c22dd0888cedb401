#pragma once
// What a protocol step hands every element set: the impregnation (which resin where, in which
// state), the rebuild of a sheet without the nodes a hole removed, and a growth of the latex. One
// struct per question, so each set's resin, cut and growth rules read the same inputs
// (docs/process.md).
#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "membra/core/vec.hpp"
#include "membra/model/elements/element_set.hpp"

namespace membra {

class Pattern;
struct Sheet;
struct Material;

struct Impregnation {
  const Pattern& pattern;  // this step's pattern (frame coordinates)
  const Pattern& all;      // its union with the patterns impregnated since the sheet last moved
  const Pattern* coats;    // the union of the coats on one face (bilayer), or nullptr
  const Sheet& sheet;      // grid, triangles, latex and lattice stiffness
  const Points& x;         // current (stretched) positions, m
  Vec2 stretch;            // frame stretch ratios so far
  const Material& resin;   // the resin's material
  int side = +1;           // +1 resin on top, -1 on the bottom
  bool bilayer = false;    // the resin sits on that face only (bilayer.hpp)
  ReleaseLevel release;    // where the release stands
};

// A sheet rebuilt without the nodes inside a hole: the old sheet's elements that survive carry
// their process state over to the new sheet's.
struct Rebuild {
  const Sheet& old_sheet;
  const Sheet& new_sheet;
  const std::vector<int>& new_of_old;  // new particle of each old one, -1 if removed

  // An old element's particles on the new sheet; false when any of them was removed.
  template <size_t N>
  bool map(const std::array<int, N>& old_ids, std::array<int, N>& ids) const {
    for (size_t c = 0; c < N; ++c) {
      ids[c] = new_of_old[static_cast<size_t>(old_ids[c])];
      if (ids[c] < 0) return false;
    }
    return true;
  }
};

// The growth of the latex at one element (grow steps, curvature maps): lengths along the paper
// direction `direction` (a unit vector) scale by `factor` and lengths across it keep theirs, or,
// when `isotropic`, all lengths scale by it (the natural metric times factor^2).
struct LocalGrowth {
  double factor = 1.0;
  bool isotropic = true;
  Vec2 direction = Vec2(1.0, 0.0);

  bool none() const { return factor == 1.0; }
  // How many times longer the paper vector d grows: sqrt((f d.u)^2 + (d x u)^2) / |d|.
  double ratio(const Vec2& d) const {
    if (isotropic) return factor;
    const double along = d.dot(direction), across = d.x() * direction.y() - d.y() * direction.x();
    return std::hypot(factor * along, across) / d.norm();
  }
  // The growth as a paper-plane stretch, raised to `exponent` (a share of it along a path):
  // f^e I, or I + (f^e - 1) u u^T.
  Eigen::Matrix2d stretch(double exponent) const {
    const double fe = std::pow(factor, exponent);
    if (isotropic) return fe * Eigen::Matrix2d::Identity();
    return Eigen::Matrix2d::Identity() + (fe - 1.0) * direction * direction.transpose();
  }
};

// The composite and resin rules of a kind that is not part of the sheet (added springs, the
// table): nothing to update with the release, no resin, no place in the design's resin maps.
struct NoResinRule {
  void update(const ReleaseLevel&) {}
  void begin_release(const Points&) {}
  int impregnate(const Impregnation&) { return 0; }
  ResinFootprint footprint(int, const Points&) const { return {}; }
  void set_resin_fraction(int, double, const ReleaseLevel&) {}
  double resin_rate(int, const Points&, const Points&, const ReleaseLevel&) const { return 0.0; }
};

// Where the latex grows, and how: each set asks it for the growth of each of its elements.
class GrowthField {
 public:
  virtual ~GrowthField() = default;
  // The growth of an element of particles `ids` at paper positions `paper` (m, the natural
  // sheet's). `group` names the element's family or kind ("stretch", "shear", "flex", "added",
  // "triangle"), for a growth that one spring family takes alone. Throws std::invalid_argument
  // where the growth is not a positive finite factor.
  virtual LocalGrowth at(std::span<const int> ids, std::span<const Vec2> paper,
                         std::string_view group) const = 0;
};

}  // namespace membra
