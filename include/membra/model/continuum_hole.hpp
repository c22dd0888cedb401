#pragma once
// A hole in the continuum sheet (docs/deformation.md, "Holes and slits on the continuum
// model"): the triangles whose centroid lies inside it go, with the particles no triangle keeps;
// the edges left along it are free. The scene cuts holes while the sheet is on its frame, and
// the mesh was made with the hole's outline, pulled back by the frame's stretch, as an edge path
// (process/prepare.cpp), so the hole is exact; a hole the mesh does not follow has the
// triangles' edges.
#include <vector>

#include "membra/model/membrane.hpp"
#include "membra/model/pattern.hpp"

namespace membra {

// Removes the triangles of the continuum sheet whose centroid on the frame (its paper position
// times m.stretch) lies inside `hole` (frame coordinates), and the particles left in no
// triangle; every element set and the
// process state carry over. Returns the number of particles removed (0, and nothing changed, if
// no triangle lies inside); `where` (if given) receives their paper positions. Throws
// std::invalid_argument if the hole would remove the whole sheet.
int punch_continuum_hole(Membrane& m, const Pattern& hole, std::vector<Vec2>* where = nullptr);

}  // namespace membra
