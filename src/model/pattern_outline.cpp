#include "membra/model/pattern_outline.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace membra {

double signed_area(const Polygon2& poly) {
  double a = 0.0;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
    a += poly[j].x() * poly[i].y() - poly[i].x() * poly[j].y();
  return 0.5 * a;
}

std::vector<Polygon2> trace_outlines(const Pattern& pattern, const Box2& frame, double step) {
  // Samples on a grid with one extra cell around the frame, where the field is forced positive,
  // so every contour closes (along the frame edge where the pattern reaches it).
  const int nx = static_cast<int>(std::ceil((frame.max.x() - frame.min.x()) / step)) + 3;
  const int ny = static_cast<int>(std::ceil((frame.max.y() - frame.min.y()) / step)) + 3;
  const double ox = frame.min.x() - step, oy = frame.min.y() - step;
  auto pos = [&](int i, int j) { return Vec2(ox + i * step, oy + j * step); };
  std::vector<double> f(static_cast<size_t>(nx) * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Vec2 p = pos(i, j);
      // Clip to the frame: outside it the field is the distance to the frame (positive).
      const double box = std::max({frame.min.x() - p.x(), p.x() - frame.max.x(),
                                   frame.min.y() - p.y(), p.y() - frame.max.y()});
      f[static_cast<size_t>(j) * nx + i] =
          (i == 0 || j == 0 || i == nx - 1 || j == ny - 1) ? step : std::max(pattern.field(p), box);
    }
  auto val = [&](int i, int j) { return f[static_cast<size_t>(j) * nx + i]; };
  // Crossing points are identified by the grid edge they lie on.
  auto edge_id = [&](int i, int j, bool vertical) {
    return 2 * (static_cast<long>(j) * nx + i) + (vertical ? 1 : 0);
  };
  std::unordered_map<long, long> next;                    // segment: start edge -> end edge
  std::unordered_map<long, std::array<double, 2>> point;  // plain storage: no Eigen alignment
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      // Corners counter-clockwise from the lower left, and the edges between them.
      const int ci[4] = {i, i + 1, i + 1, i}, cj[4] = {j, j, j + 1, j + 1};
      const long ids[4] = {edge_id(i, j, false), edge_id(i + 1, j, true), edge_id(i, j + 1, false),
                           edge_id(i, j, true)};
      double v[4];
      for (int k = 0; k < 4; ++k) v[k] = val(ci[k], cj[k]);
      struct Crossing {
        long id;
        bool leaving;  // walking counter-clockwise, from inside to outside
      };
      Crossing cross[4];
      int n = 0;
      for (int k = 0; k < 4; ++k) {
        const double a = v[k], b = v[(k + 1) % 4];
        if ((a < 0.0) == (b < 0.0)) continue;
        const double t = a / (a - b);
        const Vec2 pa = pos(ci[k], cj[k]), pb = pos(ci[(k + 1) % 4], cj[(k + 1) % 4]);
        point[ids[k]] = {pa.x() + t * (pb.x() - pa.x()), pa.y() + t * (pb.y() - pa.y())};
        cross[n++] = {ids[k], a < 0.0};
      }
      if (n == 0) continue;
      // A segment starts where the boundary walk leaves the inside (resin on its left) and ends
      // at the next crossing if the centre is inside, else at the previous one (saddle cells).
      const bool centre_inside = (v[0] + v[1] + v[2] + v[3]) < 0.0;
      for (int k = 0; k < n; ++k) {
        if (!cross[k].leaving) continue;
        const Crossing& end = centre_inside ? cross[(k + 1) % n] : cross[(k + n - 1) % n];
        next[cross[k].id] = end.id;
      }
    }
  std::vector<Polygon2> loops;
  while (!next.empty()) {
    const long start = next.begin()->first;
    Polygon2 loop;
    long at = start;
    while (true) {
      auto it = next.find(at);
      if (it == next.end()) break;
      loop.emplace_back(point[at][0], point[at][1]);
      at = it->second;
      next.erase(it);
      if (at == start) break;
    }
    // Drop vertices on straight runs (a straight edge is traced as one point per cell).
    Polygon2 simple;
    for (size_t k = 0; k < loop.size(); ++k) {
      const Vec2& prev = loop[(k + loop.size() - 1) % loop.size()];
      const Vec2& next_pt = loop[(k + 1) % loop.size()];
      const Vec2 u = loop[k] - prev, w = next_pt - loop[k];
      if (std::abs(u.x() * w.y() - u.y() * w.x()) > 1e-9 * step * step) simple.push_back(loop[k]);
    }
    if (simple.size() >= 3) loops.push_back(std::move(simple));
  }
  return loops;
}

}  // namespace membra
