#pragma once
// Positions carried from a coarser mesh of a sheet to a finer mesh of the same sheet: each fine
// vertex takes the linear interpolation, over the coarse triangle that holds its natural-sheet
// point, of the coarse vertices' positions. Where no coarse triangle holds it (the two meshes'
// chords of a curved outline or hole differ by the chord tolerance), the coarse triangle it lies
// least outside of stands in, its weights clamped to the triangle. A vertex on an opened slit has
// a copy per lip at one natural-sheet point: each copy takes the coarse triangle on its own lip's
// side (found a hair inside one of its own fine triangles). The continuum's multilevel
// release (process/multilevel.hpp) starts each finer mesh from the coarser mesh's form this way.
#include <vector>

#include "membra/core/vec.hpp"
#include "membra/geometry/triangulation.hpp"

namespace membra {

// coarse_reference, fine_reference: the natural-sheet points (x, y; z ignored) of the two meshes'
// vertices; coarse_x: a position per coarse vertex. Throws std::invalid_argument when the coarse
// mesh has no triangle.
Points prolongate_on_mesh(const Points& coarse_reference,
                          const std::vector<Triangle>& coarse_triangles, const Points& coarse_x,
                          const Points& fine_reference,
                          const std::vector<Triangle>& fine_triangles);

}  // namespace membra
