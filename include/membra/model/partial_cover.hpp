#pragma once
// Triangles of a continuum sheet that a pattern covers only in part (docs/model.md, "Resin as a
// composite"). On a mesh that follows the pattern there are none: each triangle takes the
// material at its centroid, so one that lies across the outline is resin or latex throughout.
// A run reports how many there are, so that a mesh that does not follow its pattern is seen.
#include "membra/model/pattern.hpp"
#include "membra/model/sheet.hpp"

namespace membra {

// How many of the sheet's triangles, at positions `x` (frame coordinates, m), have points
// clearly inside the pattern and points clearly outside it: farther than `margin` (m, the
// chord tolerance the mesh follows outlines to, twice) from the outline by the pattern's field,
// read as a distance (a field that is not one divided by its gradient's length), among their
// corners, edge points and interior points at sixths of the way (28 points). A straight outline
// is caught exactly: its distance is linear, its extremes over a triangle are at the corners.
int triangles_across(const Sheet& sheet, const Points& x, const Pattern& pattern, double margin);

}  // namespace membra
