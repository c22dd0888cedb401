#pragma once
// Extrinsic deformation (the paper's "adding accumulative amounts of springs to the mesh
// locally"): extra springs beside the lattice's own, in a region of the sheet. They keep the rest
// length they are given through every later step (the release does not touch them), so springs
// shorter than the sheet there pull it together and longer ones push it apart.
#include <optional>

#include "membra/model/elements/springs.hpp"
#include "membra/model/membrane.hpp"
#include "membra/model/pattern.hpp"

namespace membra {

struct AddSpringsSpec {
  PatternPtr region;  // frame coordinates (where the sheet is now, seen from above)
  std::optional<SpringFamily> along = SpringFamily::stretch;  // beside which lattice springs
  int count = 1;             // springs beside each lattice spring (>= 1)
  double stiffness = 0.0;    // k of one added spring, N/m (> 0)
  double rest_factor = 1.0;  // rest length / current length (> 0)
};

// Adds the springs beside every lattice spring (of family `along`, any when empty) whose length
// lies at least half inside the region. `count` springs in parallel act as one of count x k, and
// are stored so. Returns the number of springs added (count x pairs), 0 if the region covers none.
int add_springs(Membrane& m, const AddSpringsSpec& spec);

// Moves the rest lengths of the springs added by the last call from their current length
// (level 0) to rest_factor x that length (level 1), for a gradual path.
void set_added_springs_level(Membrane& m, int first_spring, const std::vector<double>& start_length,
                             double rest_factor, double level);

}  // namespace membra
