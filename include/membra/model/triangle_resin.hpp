#pragma once
// Which of a sheet's triangles are resin, for outputs that split the form into its two
// materials (glTF's and OBJ's materials, the continuum's mesh.svg).
#include <vector>

#include "membra/model/sheet.hpp"

namespace membra {

// Per triangle of sheet.triangles: on the continuum, whether its membrane triangle carries
// resin; on the lattice, whether the springs along its edges are resin over at least half their
// mean length (a grid triangle's edges are its stretch and shear springs).
std::vector<bool> triangle_resin(const Sheet& sheet);

}  // namespace membra
