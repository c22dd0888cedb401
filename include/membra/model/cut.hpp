#pragma once
// Topological changes (the paper's experiment 7): a cut along a polyline separates the sheet
// there; a hole removes the material inside it. Both act on the membrane as it is now, at any
// point of the process, and the simulation carries on from the current state.
#include <vector>

#include "membra/model/membrane.hpp"
#include "membra/model/pattern.hpp"

namespace membra {

// Removes every spring, bending element and triangle that crosses the polyline (frame
// coordinates: the sheet's current positions seen from above, m). A node lying exactly on the
// cut stays on the left of its direction. Returns the number of springs removed; `where` (if
// given) receives their midpoints in paper coordinates.
int cut_along(Membrane& m, const std::vector<Vec2>& polyline, std::vector<Vec2>* where = nullptr);

// Removes the particles whose current position (seen from above) lies inside `hole`, with the
// springs, bending elements and triangles that touch them, and rebuilds the lattice around the
// hole so the new edge carries half-cell springs and masses like any other boundary. Everything
// the process did (resin, growth, added springs, pins, earlier cuts) carries over. Returns the
// number of particles removed (0 if the hole covers none); `where` (if given) receives their
// paper positions. Throws std::invalid_argument if the hole would remove the whole sheet.
int punch_hole(Membrane& m, const Pattern& hole, std::vector<Vec2>* where = nullptr);

}  // namespace membra
