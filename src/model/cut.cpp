#include "membra/model/cut.hpp"

#include "membra/model/continuum_hole.hpp"
#include "membra/model/continuum_slit.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>
#include <tuple>

namespace membra {
namespace {

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// True if segment p-q crosses the cut segment c0-c1. Sides are taken with >= 0 as "left", so a
// point on the cut line belongs to one side consistently and the cut never leaves a node joined
// to both sides.
bool crosses(const Vec2& p, const Vec2& q, const Vec2& c0, const Vec2& c1) {
  const Vec2 c = c1 - c0;
  const double sp = cross(c, p - c0), sq = cross(c, q - c0);
  if ((sp >= 0.0) == (sq >= 0.0)) return false;
  const Vec2 x = p + (sp / (sp - sq)) * (q - p);
  const double s = (x - c0).dot(c) / c.squaredNorm();
  return s >= 0.0 && s <= 1.0;
}

bool crosses_polyline(const Vec2& p, const Vec2& q, const std::vector<Vec2>& line) {
  for (size_t k = 0; k + 1 < line.size(); ++k)
    if (crosses(p, q, line[k], line[k + 1])) return true;
  return false;
}

using TriKey = std::array<int, 3>;

int node_id(const GridSheet& g, int p) {
  const auto [i, j] = g.node(p);
  return j * g.nx() + i;
}

TriKey tri_key(const GridSheet& g, const Triangle& t) {
  TriKey k{node_id(g, t[0]), node_id(g, t[1]), node_id(g, t[2])};
  std::sort(k.begin(), k.end());
  return k;
}

}  // namespace

int cut_along(Membrane& m, const std::vector<Vec2>& line, std::vector<Vec2>* where) {
  if (m.sheet.continuum()) return cut_continuum_slit(m, line, where);
  if (line.size() < 2) throw std::invalid_argument("a cut needs at least two points");
  const Points& x = m.state.x;
  const CrossesCut crosses = [&](int p, int q) {
    return crosses_polyline(x.col(p).head<2>(), x.col(q).head<2>(), line);
  };
  Model& model = m.sheet.model;
  // The springs, the lattice's and the added, decide whether the line cuts the sheet at all (and
  // where, for the report).
  int removed = 0;
  const auto count_cut = [&](const auto& springs) {
    const std::vector<bool> keep = survivors_of_cut(springs, crosses);
    for (int s = 0; s < springs.size(); ++s) {
      if (keep[static_cast<size_t>(s)]) continue;
      ++removed;
      if (!where) continue;
      const Vec3 mid =
          0.5 * (model.reference.col(springs.a[s]) + model.reference.col(springs.b[s]));
      where->push_back(mid.head<2>());
    }
  };
  count_cut(model.springs);
  count_cut(model.added_springs);
  if (removed == 0) return 0;
  model.for_each_set([&](auto& set) { set.filter(survivors_of_cut(set, crosses)); });
  std::erase_if(m.sheet.triangles, [&](const Triangle& t) {
    return crosses(t[0], t[1]) || crosses(t[1], t[2]) || crosses(t[2], t[0]);
  });
  return removed;
}

namespace {

// The sheet rebuilt on the nodes outside the hole (the new edge carries half stiffness), its
// particles carrying the old ones' state, pins and process state.
Membrane rebuild_without(const Membrane& m, const std::vector<bool>& keep_node,
                         std::vector<int>& new_of_old) {
  const GridSheet& g = m.sheet.grid;
  GridSpec spec{g.width(), g.height(), g.nx(), g.ny()};
  const double hx = g.hx(), hy = g.hy();
  const int nx = g.nx();
  NodeMask mask = [&](double px, double py) {
    const int i = static_cast<int>(std::lround(px / hx)),
              j = static_cast<int>(std::lround(py / hy));
    return keep_node[static_cast<size_t>(j) * nx + i];
  };
  Sheet rebuilt;
  try {
    rebuilt = build_sheet(spec, m.sheet.options, mask);
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument("the hole removes the whole sheet");
  }
  Membrane n = make_membrane(std::move(rebuilt));
  const GridSheet& ng = n.sheet.grid;
  new_of_old.assign(static_cast<size_t>(m.sheet.model.num_particles()), -1);
  for (int p = 0; p < n.sheet.model.num_particles(); ++p) {
    const auto [i, j] = ng.node(p);
    new_of_old[static_cast<size_t>(g.particle(i, j))] = p;
  }
  carry_process_state(m, new_of_old, n);
  return n;
}

}  // namespace

int punch_hole(Membrane& m, const Pattern& hole, std::vector<Vec2>* where) {
  if (m.sheet.continuum()) return punch_continuum_hole(m, hole, where);
  const GridSheet& g = m.sheet.grid;
  const Model& old = m.sheet.model;
  std::vector<bool> keep_node(static_cast<size_t>(g.nx()) * g.ny(), false);
  int inside = 0;
  for (int p = 0; p < old.num_particles(); ++p) {
    const bool in = hole.contains(m.state.x.col(p).head<2>());
    keep_node[node_id(g, p)] = !in;
    inside += in;
    if (in && where) where->push_back(old.reference.col(p).head<2>());
  }
  if (inside == 0) return 0;
  std::vector<int> new_of_old;
  Membrane n = rebuild_without(m, keep_node, new_of_old);
  // Triangles that still exist (the hinges' rule reads them), then each set's elements.
  std::map<TriKey, bool> old_tri;
  for (const Triangle& t : m.sheet.triangles) old_tri[tri_key(g, t)] = true;
  std::erase_if(n.sheet.triangles,
                [&](const Triangle& t) { return !old_tri.contains(tri_key(n.sheet.grid, t)); });
  const Rebuild rebuild{m.sheet, n.sheet, new_of_old};
  n.sheet.model.for_each_set_with(old,
                                  [&](auto& set, const auto& from) { set.carry(from, rebuild); });
  n.sheet.model.table.cover(n.sheet.model.mass);  // the table, if any, under the rebuilt sheet
  update_elements(n);
  const int removed = old.num_particles() - n.sheet.model.num_particles();
  m = std::move(n);
  return removed;
}

}  // namespace membra
