#include "membra/io/obj.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "membra/core/input_error.hpp"
#include "membra/core/units.hpp"
#include "membra/geometry/triangulation.hpp"

namespace membra {

void write_obj(std::ostream& out, const Points& x, const std::vector<Triangle>& triangles) {
  out << "# membra mesh; units: mm\n";
  char line[128];
  for (Eigen::Index p = 0; p < x.cols(); ++p) {
    const Vec3 q = x.col(p) / units::mm;
    std::snprintf(line, sizeof line, "v %.10g %.10g %.10g\n", q.x(), q.y(), q.z());
    out << line;
  }
  for (const Triangle& t : triangles)
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

void write_obj(std::ostream& out, const Points& x, const std::vector<Triangle>& triangles,
               const ObjLayers& layers) {
  const auto n = static_cast<size_t>(x.cols());
  if (layers.uv.size() != n || layers.resin.size() != triangles.size())
    throw std::invalid_argument("write_obj: texture coordinates or materials do not match");
  out << "# membra mesh; units: mm; vt: the flat sheet\n";
  if (!layers.mtllib.empty()) out << "mtllib " << layers.mtllib << '\n';
  char line[128];
  for (Eigen::Index p = 0; p < x.cols(); ++p) {
    const Vec3 q = x.col(p) / units::mm;
    std::snprintf(line, sizeof line, "v %.10g %.10g %.10g\n", q.x(), q.y(), q.z());
    out << line;
  }
  const Points normals = vertex_normals(x, triangles);
  for (Eigen::Index p = 0; p < x.cols(); ++p) {
    const Vec3 m = normals.col(p);
    std::snprintf(line, sizeof line, "vn %.6f %.6f %.6f\n", m.x(), m.y(), m.z());
    out << line;
  }
  for (const Vec2& t : layers.uv) {
    std::snprintf(line, sizeof line, "vt %.8f %.8f\n", t.x(), t.y());
    out << line;
  }
  for (const bool resin : {false, true}) {
    if (std::find(layers.resin.begin(), layers.resin.end(), resin) == layers.resin.end()) continue;
    const char* name = resin ? "resin" : "latex";
    out << "g " << name << "\nusemtl " << name << '\n';
    for (size_t k = 0; k < triangles.size(); ++k) {
      if (layers.resin[k] != resin) continue;
      out << 'f';
      for (int c = 0; c < 3; ++c) {
        const int i = triangles[k][c] + 1;
        out << ' ' << i << '/' << i << '/' << i;
      }
      out << '\n';
    }
  }
}

void write_mtl(std::ostream& out) {
  out << "# membra materials\n"
         "newmtl latex\nKd 0.93 0.84 0.62\nKa 0 0 0\nKs 0.05 0.05 0.05\nNs 10\nd 1\nillum 2\n\n"
         "newmtl resin\nKd 0.13 0.38 0.75\nKa 0 0 0\nKs 0.5 0.5 0.5\nNs 80\nd 0.9\nillum 2\n";
}

namespace {

constexpr size_t kMaxObjVertices = 50'000'000;  // far beyond a design target; bounds memory

[[noreturn]] void obj_error(const std::string& where, long line, const std::string& what) {
  throw InputError(where, "line " + std::to_string(line) + ": " + what);
}

}  // namespace

ObjMesh read_obj(std::istream& in, const std::string& where) {
  std::vector<Vec3> v;
  std::vector<Triangle> tris;
  std::string text;
  long line = 0;
  while (std::getline(in, text)) {
    ++line;
    std::istringstream ls(text);
    std::string kind;
    if (!(ls >> kind) || kind[0] == '#') continue;
    if (kind == "v") {
      double c[3];
      for (double& ci : c) {
        std::string tok;
        if (!(ls >> tok)) obj_error(where, line, "a vertex needs x y z");
        char* end = nullptr;
        ci = std::strtod(tok.c_str(), &end);
        if (end == tok.c_str() || *end != '\0' || !std::isfinite(ci))
          obj_error(where, line, "'" + tok + "' is not a finite number");
      }
      if (v.size() >= kMaxObjVertices) obj_error(where, line, "too many vertices");
      v.emplace_back(c[0] * units::mm, c[1] * units::mm, c[2] * units::mm);
    } else if (kind == "f") {
      std::vector<int> corner;
      std::string tok;
      while (ls >> tok) {
        const std::string head = tok.substr(0, tok.find('/'));
        char* end = nullptr;
        const long k = std::strtol(head.c_str(), &end, 10);
        if (head.empty() || *end != '\0' || k == 0)
          obj_error(where, line, "'" + tok + "' is not a vertex index");
        const long n = static_cast<long>(v.size());
        const long idx = k > 0 ? k - 1 : n + k;  // negative: relative to the end
        if (idx < 0 || idx >= n)
          obj_error(where, line,
                    "vertex index " + std::to_string(k) + " is out of range (" + std::to_string(n) +
                        " vertices so far)");
        corner.push_back(static_cast<int>(idx));
      }
      if (corner.size() < 3) obj_error(where, line, "a face needs at least 3 corners");
      for (size_t c = 1; c + 1 < corner.size(); ++c)
        tris.emplace_back(corner[0], corner[c], corner[c + 1]);
    }
  }
  if (tris.empty()) throw InputError(where, "no faces: an OBJ target needs triangles");
  ObjMesh mesh;
  mesh.x.resize(3, static_cast<Eigen::Index>(v.size()));
  for (size_t i = 0; i < v.size(); ++i) mesh.x.col(static_cast<Eigen::Index>(i)) = v[i];
  mesh.triangles = std::move(tris);
  return mesh;
}

}  // namespace membra
