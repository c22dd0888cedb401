#pragma once
// What a protocol step hands every element set: the impregnation (which resin where, in which
// state) and the rebuild of a sheet without the nodes a hole removed. One struct per question,
// so each set's resin rule and cut rule read the same inputs (docs/process.md).
#include <array>
#include <cstddef>
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

}  // namespace membra
