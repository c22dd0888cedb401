#pragma once
// How far apart two end states of the same sheet are: the root-mean-square distance between
// corresponding particles, after the best rigid motion (rotation and translation, no mirror)
// when the sheet is free to move. simulation.explore tells distinct stable forms apart by it.
#include "membra/core/vec.hpp"

namespace membra {

// RMS of |R a_p + t - b_p| over the particles, minimised over proper rotations R and
// translations t (Kabsch) when `align`, else with R = I, t = 0. Throws std::invalid_argument
// when a and b differ in size.
double form_distance(const Points& a, const Points& b, bool align);

}  // namespace membra
