#include "membra/io/mesh_svg.hpp"

#include <cstdio>
#include <string>

#include "membra/core/units.hpp"

namespace membra {
namespace {

std::string mesh_mm(double metres) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", metres / units::mm);
  return buf;
}

}  // namespace

void write_mesh_svg(std::ostream& out, const Points& x, const std::vector<Triangle>& triangles,
                    const std::vector<bool>& resin, double width, double height) {
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<!-- membra continuum mesh of the natural sheet, true scale, units mm; orange = resin "
         "-->\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << mesh_mm(width) << "mm\" height=\""
      << mesh_mm(height) << "mm\" viewBox=\"0 0 " << mesh_mm(width) << " " << mesh_mm(height)
      << "\">\n"
      << "  <g stroke=\"#303030\" stroke-width=\"0.08\" stroke-linejoin=\"round\">\n";
  for (size_t t = 0; t < triangles.size(); ++t) {
    out << "    <polygon fill=\"" << (t < resin.size() && resin[t] ? "#f0a040" : "white")
        << "\" points=\"";
    for (int k = 0; k < 3; ++k) {
      const int p = triangles[t][k];
      out << (k ? " " : "") << mesh_mm(x(0, p)) << "," << mesh_mm(height - x(1, p));
    }
    out << "\"/>\n";
  }
  out << "  </g>\n</svg>\n";
}

}  // namespace membra
