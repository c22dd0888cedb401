#pragma once
// Wavefront OBJ output of a triangulated sheet.
#include <ostream>
#include <vector>

#include "membra/geometry/triangulation.hpp"
#include "membra/geometry/vec.hpp"

namespace membra {

// Writes vertices (positions in m, written in mm) and triangles as an OBJ mesh. Numbers are
// printed with enough digits to round-trip, and always the same way, so equal states give equal
// bytes.
void write_obj(std::ostream& out, const Points& x, const std::vector<Triangle>& triangles);

}  // namespace membra
