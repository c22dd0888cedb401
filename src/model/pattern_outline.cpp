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

namespace {

// The field sampled on a grid with one extra cell around the frame, where it is forced positive,
// so that every contour closes (along the frame edge where the pattern reaches it).
struct Samples {
  int nx = 0, ny = 0;
  double ox = 0.0, oy = 0.0, step = 0.0;
  std::vector<double> f;
  Vec2 pos(int i, int j) const { return Vec2(ox + i * step, oy + j * step); }
  double val(int i, int j) const { return f[static_cast<size_t>(j) * nx + i]; }
  // Crossing points are identified by the grid edge they lie on.
  long edge_id(int i, int j, bool vertical) const {
    return 2 * (static_cast<long>(j) * nx + i) + (vertical ? 1 : 0);
  }
};

Samples sample(const Pattern& pattern, const Box2& frame, double step) {
  Samples g;
  g.step = step;
  g.nx = static_cast<int>(std::ceil((frame.max.x() - frame.min.x()) / step)) + 3;
  g.ny = static_cast<int>(std::ceil((frame.max.y() - frame.min.y()) / step)) + 3;
  g.ox = frame.min.x() - step, g.oy = frame.min.y() - step;
  g.f.resize(static_cast<size_t>(g.nx) * g.ny);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const Vec2 p = g.pos(i, j);
      // Clip to the frame: outside it the field is the distance to the frame (positive).
      const double box = std::max({frame.min.x() - p.x(), p.x() - frame.max.x(),
                                   frame.min.y() - p.y(), p.y() - frame.max.y()});
      g.f[static_cast<size_t>(j) * g.nx + i] = (i == 0 || j == 0 || i == g.nx - 1 || j == g.ny - 1)
                                                   ? step
                                                   : std::max(pattern.field(p), box);
    }
  return g;
}

// Marching squares: for each cell, the contour segments through it as start edge -> end edge,
// and the crossing point on each edge.
void segments(const Samples& g, std::unordered_map<long, long>& next,
              std::unordered_map<long, std::array<double, 2>>& point) {
  for (int j = 0; j + 1 < g.ny; ++j)
    for (int i = 0; i + 1 < g.nx; ++i) {
      // Corners counter-clockwise from the lower left, and the edges between them.
      const int ci[4] = {i, i + 1, i + 1, i}, cj[4] = {j, j, j + 1, j + 1};
      const long ids[4] = {g.edge_id(i, j, false), g.edge_id(i + 1, j, true),
                           g.edge_id(i, j + 1, false), g.edge_id(i, j, true)};
      double v[4];
      for (int k = 0; k < 4; ++k) v[k] = g.val(ci[k], cj[k]);
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
        const Vec2 pa = g.pos(ci[k], cj[k]), pb = g.pos(ci[(k + 1) % 4], cj[(k + 1) % 4]);
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
}

// Drops vertices on straight runs (a straight edge is traced as one point per cell). Where the
// field is zero at a sample, the crossings of the edges that meet there coincide: they are one
// vertex first, or their zero-length edge would read as straight and drop a corner (a strip's
// side meeting the frame's edge came out slanted by a cell over its length).
Polygon2 simplify(const Polygon2& traced, double step) {
  const double same = 1e-9 * step;
  Polygon2 loop;
  for (const Vec2& p : traced)
    if (loop.empty() || (p - loop.back()).norm() > same) loop.push_back(p);
  while (loop.size() > 1 && (loop.back() - loop.front()).norm() <= same) loop.pop_back();
  Polygon2 simple;
  for (size_t k = 0; k < loop.size(); ++k) {
    const Vec2& prev = loop[(k + loop.size() - 1) % loop.size()];
    const Vec2& next_pt = loop[(k + 1) % loop.size()];
    const Vec2 u = loop[k] - prev, w = next_pt - loop[k];
    if (std::abs(u.x() * w.y() - u.y() * w.x()) > 1e-9 * step * step) simple.push_back(loop[k]);
  }
  return simple;
}

}  // namespace

std::vector<Polygon2> trace_outlines(const Pattern& pattern, const Box2& frame, double step) {
  const Samples g = sample(pattern, frame, step);
  std::unordered_map<long, long> next;                    // segment: start edge -> end edge
  std::unordered_map<long, std::array<double, 2>> point;  // plain storage: no Eigen alignment
  segments(g, next, point);
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
    Polygon2 simple = simplify(loop, step);
    if (simple.size() >= 3) loops.push_back(std::move(simple));
  }
  return loops;
}

}  // namespace membra
