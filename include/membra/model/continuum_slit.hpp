#pragma once
// A slit in the continuum sheet (docs/deformation.md, "Holes and slits on the continuum model"):
// the mesh was made with the slit's polyline, pulled back from the frame by the stretch, as an
// edge path (process/prepare.cpp), and the cut opens it. Every particle on it whose triangles
// the slit separates becomes one particle per side, so the slit's two lips move apart; a slit's
// end inside the sheet stays one particle (the tip), an end on the outline opens the rim.
#include <vector>

#include "membra/model/membrane.hpp"

namespace membra {

// Opens the slit along `line` (frame coordinates, m): the mesh edges lying on it, on the frame
// (paper positions times m.stretch, within 1 um). Every element set, the frame, the pins and the
// state carry over to the copies. Returns the number of mesh edges opened (0, and nothing
// changed, when no edge lies on the line); `where` (if given) receives their midpoints (paper).
int cut_continuum_slit(Membrane& m, const std::vector<Vec2>& line,
                       std::vector<Vec2>* where = nullptr);

// Splits every particle whose triangles meet only there (two fans joined at a corner, as a hole
// leaves where its edge reaches a slit's tip) into one particle per fan, as a slit does. Returns
// the number of particles added.
int separate_pinched_particles(Membrane& m);

}  // namespace membra
