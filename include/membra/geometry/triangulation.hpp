#pragma once
// Triangles of a grid sheet, for drawing and measuring.
#include <vector>

#include <Eigen/Core>

#include "membra/geometry/grid_sheet.hpp"

namespace membra {

using Triangle = Eigen::Vector3i;  // particle indices, counter-clockwise seen from +z

// Splits every active cell into two triangles. The diagonal alternates with the parity of
// (i + j) so that the mesh has no preferred direction (a single diagonal would bias measures).
std::vector<Triangle> triangulate(const GridSheet& sheet);

}  // namespace membra
