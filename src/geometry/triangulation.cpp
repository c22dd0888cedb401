#include "membra/geometry/triangulation.hpp"

namespace membra {

std::vector<Triangle> triangulate(const GridSheet& sheet) {
  std::vector<Triangle> tris;
  for (int j = 0; j + 1 < sheet.ny(); ++j) {
    for (int i = 0; i + 1 < sheet.nx(); ++i) {
      if (!sheet.cell_active(i, j)) continue;
      const int a = sheet.particle(i, j), b = sheet.particle(i + 1, j);
      const int c = sheet.particle(i + 1, j + 1), d = sheet.particle(i, j + 1);
      if ((i + j) % 2 == 0) {
        tris.emplace_back(a, b, c);
        tris.emplace_back(a, c, d);
      } else {
        tris.emplace_back(a, b, d);
        tris.emplace_back(b, c, d);
      }
    }
  }
  return tris;
}

}  // namespace membra
