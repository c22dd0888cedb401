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

// What a form's OBJ carries besides its triangles: the flat sheet as texture coordinates (per
// vertex, flat_uv), which triangles are resin, and the material library the groups name.
struct ObjLayers {
  std::vector<Vec2> uv;
  std::vector<bool> resin;  // per triangle
  std::string mtllib;       // e.g. "final.mtl"
};
// The form with smooth normals (vn), texture coordinates (vt) and its triangles in two groups,
// `g latex` and `g resin`, each with `usemtl` of the same name from `layers.mtllib`. Throws
// std::invalid_argument when the layers' sizes disagree with the mesh.
void write_obj(std::ostream& out, const Points& x, const std::vector<Triangle>& triangles,
               const ObjLayers& layers);
// The material library for it: latex (a pale amber) and resin (a translucent blue, as the
// stencil draws it).
void write_mtl(std::ostream& out);

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
