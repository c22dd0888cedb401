#include "membra/io/ply.hpp"

#include <cmath>
#include <cstdio>

#include "membra/core/units.hpp"

namespace membra {

void write_ply(std::ostream& out, const Points& x, const std::vector<Triangle>& triangles,
               const std::vector<Rgb>& colors, const std::vector<VertexProperty>& properties) {
  out << "ply\nformat ascii 1.0\ncomment membra mesh; units: mm\n";
  out << "element vertex " << x.cols()
      << "\nproperty float x\nproperty float y\nproperty float z\n";
  out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  for (const auto& p : properties) out << "property float " << p.name << "\n";
  out << "element face " << triangles.size() << "\nproperty list uchar int vertex_indices\n";
  out << "end_header\n";
  char line[96];
  auto byte = [](float c) { return static_cast<int>(std::lround(255.0f * c)); };
  for (Eigen::Index v = 0; v < x.cols(); ++v) {
    const Vec3 q = x.col(v) / units::mm;
    std::snprintf(line, sizeof line, "%.9g %.9g %.9g", q.x(), q.y(), q.z());
    out << line << ' ' << byte(colors[v].x()) << ' ' << byte(colors[v].y()) << ' '
        << byte(colors[v].z());
    for (const auto& p : properties) {
      std::snprintf(line, sizeof line, " %.9g", p.values[v]);
      out << line;
    }
    out << '\n';
  }
  for (const Triangle& t : triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

}  // namespace membra
