#include "membra/io/obj.hpp"

#include <cstdio>

#include "membra/model/units.hpp"

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

}  // namespace membra
