#pragma once
// The ranges of stress, strain and force over the elements, and a per-vertex stress for pictures,
// both from every element set's read-out.
#include <vector>

#include "membra/model/model.hpp"

namespace membra {

// The ranges of every element set's read-out (element_set.hpp's ElementStress): 0 where no
// element has the quantity (no spring on a continuum sheet has a force).
struct StressRanges {
  double min_stress = 0.0, max_stress = 0.0;  // Pa, over elements that carry a stress
  double min_strain = 0.0, max_strain = 0.0;  // over elements with a strain
  double min_force = 0.0, max_force = 0.0;    // N, over axial elements (springs)
};

// The ranges at positions x for a sheet of the given thickness (m).
StressRanges stress_ranges(const Model& model, const Points& x, double thickness);

// Mean stress of the elements meeting at each particle that carry one (Pa), for colouring: every
// element set's read-out (model/elements/) at positions x for a sheet of that thickness (m).
std::vector<double> vertex_stress(const Model& model, const Points& x, double thickness);

}  // namespace membra
