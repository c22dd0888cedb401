#include "membra/geometry/triangulation.hpp"

#include <algorithm>

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

std::map<std::pair<int, int>, int> edge_counts(const std::vector<Triangle>& triangles) {
  std::map<std::pair<int, int>, int> count;
  for (const Triangle& t : triangles)
    for (int k = 0; k < 3; ++k) ++count[std::minmax(t[k], t[(k + 1) % 3])];
  return count;
}

std::vector<bool> boundary_vertices(int n, const std::vector<Triangle>& triangles) {
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * triangles.size());
  for (const Triangle& t : triangles)
    for (int k = 0; k < 3; ++k) edges.push_back(edge_key(t[k], t[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  std::vector<bool> on(static_cast<size_t>(n), false);
  for (size_t i = 0; i < edges.size();) {
    size_t j = i + 1;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i == 1) on[edges[i] >> 32] = on[edges[i] & 0xffffffffu] = true;
    i = j;
  }
  return on;
}

Points vertex_normals(const Points& x, const std::vector<Triangle>& triangles) {
  Points n = Points::Zero(3, x.cols());
  for (const Triangle& t : triangles) {
    const Vec3 a = (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0]));
    for (int k = 0; k < 3; ++k) n.col(t[k]) += a;
  }
  for (Eigen::Index p = 0; p < n.cols(); ++p) {
    const double len = n.col(p).norm();
    n.col(p) = len > 0.0 ? Vec3(n.col(p) / len) : Vec3::UnitZ();
  }
  return n;
}

std::vector<Vec2> flat_uv(const Points& flat) {
  std::vector<Vec2> uv;
  if (flat.cols() == 0) return uv;
  const Vec2 lo = flat.topRows<2>().rowwise().minCoeff();
  const Vec2 extent = flat.topRows<2>().rowwise().maxCoeff() - lo;
  const double side = std::max(extent.maxCoeff(), 1e-300);
  uv.reserve(static_cast<size_t>(flat.cols()));
  for (Eigen::Index p = 0; p < flat.cols(); ++p)
    uv.emplace_back((flat.col(p).head<2>() - lo) / side);
  return uv;
}

}  // namespace membra
