#pragma once
// Triangles of a sheet, for drawing and measuring, and what drawing them needs: smooth normals
// and the flat sheet as texture coordinates.
#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "membra/core/vec.hpp"
#include "membra/geometry/grid_sheet.hpp"

namespace membra {

using Triangle = Eigen::Vector3i;  // particle indices, counter-clockwise seen from +z

// Splits every active cell into two triangles. The diagonal alternates with the parity of
// (i + j) so that the mesh has no preferred direction (a single diagonal would bias measures).
std::vector<Triangle> triangulate(const GridSheet& sheet);

// How many triangles share each edge, the edge as (smaller, larger) particle index: 1 on the
// mesh's boundary (outline, holes, opened slits), 2 inside.
std::map<std::pair<int, int>, int> edge_counts(const std::vector<Triangle>& triangles);

// An undirected edge (a, b) as one number, sortable and hashable: the smaller index in the high
// 32 bits.
inline std::uint64_t edge_key(int a, int b) {
  return static_cast<std::uint64_t>(std::min(a, b)) << 32 |
         static_cast<std::uint32_t>(std::max(a, b));
}

// Which of the n vertices lie on the mesh's boundary: on an edge only one triangle has (the
// outline, holes, opened slits). From sorted edge keys rather than edge_counts' map: the viewer
// asks for it every frame (through the curvature).
std::vector<bool> boundary_vertices(int n, const std::vector<Triangle>& triangles);

// Unit vertex normals, the area-weighted mean of the triangles' around each vertex (+z where a
// vertex has none, or they cancel).
Points vertex_normals(const Points& x, const std::vector<Triangle>& triangles);

// Texture coordinates of the flat sheet: (x, y) of `flat` less its lower-left corner, over its
// larger side, so the sheet fills [0, 1] along that side and keeps its proportions (origin at the
// lower left, v upwards, as OBJ counts them).
std::vector<Vec2> flat_uv(const Points& flat);

}  // namespace membra
