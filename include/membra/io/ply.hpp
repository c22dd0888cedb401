#pragma once
// PLY (ASCII) output of a triangulated sheet with per-vertex colours and named scalar
// properties, for MeshLab, Blender, Rhino and the like.
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "membra/geometry/triangulation.hpp"
#include "membra/measure/colormap.hpp"

namespace membra {

// One per-vertex scalar, written as a float property named `name`.
struct VertexProperty {
  std::string name;
  std::vector<double> values;
};

// Vertices in mm (positions given in m), colours 0..255, then the properties, then triangles.
void write_ply(std::ostream& out, const Points& x, const std::vector<Triangle>& triangles,
               const std::vector<Rgb>& colors, const std::vector<VertexProperty>& properties);

}  // namespace membra
