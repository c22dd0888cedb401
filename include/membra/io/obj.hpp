#pragma once
// Wavefront OBJ: output of a triangulated sheet, and input of target meshes.
#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "membra/core/vec.hpp"
#include "membra/geometry/triangulation.hpp"

namespace membra {

// Writes vertices (positions in m, written in mm) and triangles as an OBJ mesh. Numbers are
// printed with enough digits to round-trip, and always the same way, so equal states give equal
// bytes.
void write_obj(std::ostream& out, const Points& x, const std::vector<Triangle>& triangles);

struct ObjMesh {
  Points x;  // m (the file's numbers are read as mm)
  std::vector<Triangle> triangles;
};

// Reads the vertices ("v x y z") and faces ("f a b c ...", indices 1-based or negative, "a/t/n"
// forms, polygons split into fans) of an OBJ file in mm; other statements are skipped. Throws
// InputError at `where` naming the line for a malformed number, a non-finite coordinate, an index
// out of range, a face with fewer than 3 corners, or a file with no face.
ObjMesh read_obj(std::istream& in, const std::string& where);

}  // namespace membra
