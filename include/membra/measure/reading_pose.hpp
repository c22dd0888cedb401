#pragma once
// The pose a released form is shown and written in, as the piece would lie on a table
// (docs/outputs.md, "The pose"): the best-fit quadric's tangent plane horizontal, the side the
// form opens towards up (a bowl opens upward), x and y along the quadric's principal directions
// (a saddle's axes along x and y), the one nearer the paper's x axis as x (the paper's x itself
// on a nearly round cap, whose principal directions are arbitrary); centred on the origin
// in x and y, its lowest point at z = 0.
#include "membra/geometry/rigid_fit.hpp"
#include "membra/measure/quadric_fit.hpp"

namespace membra {

// The motion that poses x (3 x N, m). A flat or folded form, whose quadric does not describe
// it, is posed by its best-fit plane instead (its normal turned to the quadric's side, x along
// the paper's x axis as it lies in that plane).
RigidMotion reading_pose(const Points& x, const QuadricFit& quadric);

}  // namespace membra
