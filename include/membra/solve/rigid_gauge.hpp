#pragma once
// A sheet held by nothing can move rigidly: its energy's Hessian has six zero eigenvalues, and
// Newton's linear systems are singular. The gauge removes exactly these six motions, whatever
// the sheet's orientation: three particles a (near the centre), b (far from a) and c (far from
// the line ab) define a frame with ab along its x axis and abc in its xy plane; in that frame,
// holding all of a, y and z of b, and z of c leaves every form reachable (rotate it so that b
// lies on a's x line and c in a's xy plane) and fixes nothing else. Holding b's y and z in the
// sheet's own axes would forbid ab from shortening unless ab ran along x (docs/solver.md).
//
// A sheet on a table (model/elements/table_contact.hpp) is held up by the plane and gravity: only
// its motions in the plane are free, a translation in x and y and a turn about z. The planar
// gauge turns the sheet about z only, so that b lies on a's x line, and holds x and y of a and y
// of b.
#include <vector>

#include "membra/core/vec.hpp"
#include "membra/model/model.hpp"

namespace membra {

struct RigidGauge {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // sheet axes -> gauge frame
  std::vector<int> held;  // coordinate numbers 3 p + c (in the gauge frame) to hold
};

// The gauge for positions x (at least three particles, not all on one line).
RigidGauge rigid_gauge(const Points& x);

// The planar gauge for positions x (at least two particles, not one above the other).
RigidGauge planar_gauge(const Points& x);

// Whether the table holds the sheet up: there is one, and gravity presses the sheet onto it.
bool held_by_table(const Model& model);

// The gauge a sheet that no pin holds takes: the planar one on a table, else the rigid one.
RigidGauge free_sheet_gauge(const Model& model, const Points& x);

}  // namespace membra
