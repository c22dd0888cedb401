#include "membra/model/cut.hpp"

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

void filter_springs(Membrane& m, const std::vector<bool>& keep) {
  m.sheet.model.springs.filter(keep);
  for (auto* v : {&m.natural_length, &m.latex_stiffness, &m.resin_fraction, &m.resin_stiffness,
                  &m.resin_length, &m.frame_length}) {
    size_t w = 0;
    for (size_t s = 0; s < v->size(); ++s)
      if (keep[s]) (*v)[w++] = (*v)[s];
    v->resize(w);
  }
}

void filter_bending(Membrane& m, const std::vector<bool>& keep) {
  Bending& b = m.sheet.model.bending;
  Bending out;
  std::vector<double> latex, resin, fraction;
  for (int e = 0; e < b.size(); ++e) {
    if (!keep[e]) continue;
    out.v.push_back(b.v[e]);
    out.stiffness.push_back(b.stiffness[e]);
    out.factor.push_back(b.factor[e]);
    latex.push_back(m.latex_bending[e]);
    resin.push_back(m.resin_bending[e]);
    fraction.push_back(m.bending_fraction[e]);
  }
  b = std::move(out);
  m.latex_bending = std::move(latex);
  m.resin_bending = std::move(resin);
  m.bending_fraction = std::move(fraction);
}

void filter_hinges(Membrane& m, const std::vector<bool>& keep) {
  Hinges& h = m.sheet.model.hinges;
  Hinges out;
  std::vector<double> full, coverage;
  for (int e = 0; e < h.size(); ++e) {
    if (!keep[e]) continue;
    out.add(h.v[e], h.moment[e]);
    full.push_back(m.hinge_full_moment[e]);
    coverage.push_back(m.hinge_coverage[e]);
  }
  h = std::move(out);
  m.hinge_full_moment = std::move(full);
  m.hinge_coverage = std::move(coverage);
}

using SpringKey = std::tuple<int, int, SpringFamily>;
using BendKey = std::array<int, 3>;
using TriKey = std::array<int, 3>;

int node_id(const GridSheet& g, int p) {
  const auto [i, j] = g.node(p);
  return j * g.nx() + i;
}

SpringKey spring_key(const GridSheet& g, const Springs& sp, int s) {
  const int a = node_id(g, sp.a[s]), b = node_id(g, sp.b[s]);
  return {std::min(a, b), std::max(a, b), sp.family[s]};
}

TriKey tri_key(const GridSheet& g, const Triangle& t) {
  TriKey k{node_id(g, t[0]), node_id(g, t[1]), node_id(g, t[2])};
  std::sort(k.begin(), k.end());
  return k;
}

double composite_bending(double latex, double resin, double fraction) {
  return fraction > 0.0 ? 1.0 / ((1.0 - fraction) / latex + fraction / (latex + resin)) : latex;
}

}  // namespace

int cut_along(Membrane& m, const std::vector<Vec2>& line, std::vector<Vec2>* where) {
  if (line.size() < 2) throw std::invalid_argument("a cut needs at least two points");
  const Points& x = m.state.x;
  auto xy = [&](int p) -> Vec2 { return x.col(p).head<2>(); };
  Springs& sp = m.sheet.model.springs;
  std::vector<bool> keep(sp.size(), true);
  int removed = 0;
  for (int s = 0; s < sp.size(); ++s)
    if (crosses_polyline(xy(sp.a[s]), xy(sp.b[s]), line)) {
      keep[s] = false;
      ++removed;
      if (where)
        where->push_back(
            0.5 * (m.sheet.model.reference.col(sp.a[s]) + m.sheet.model.reference.col(sp.b[s]))
                      .head<2>());
    }
  if (removed == 0) return 0;
  filter_springs(m, keep);

  const Bending& b = m.sheet.model.bending;
  std::vector<bool> keep_bend(b.size(), true);
  for (int e = 0; e < b.size(); ++e)
    keep_bend[e] = !crosses_polyline(xy(b.v[e][0]), xy(b.v[e][1]), line) &&
                   !crosses_polyline(xy(b.v[e][1]), xy(b.v[e][2]), line);
  filter_bending(m, keep_bend);

  auto cut_triangle = [&](int p0, int p1, int p2) {
    return crosses_polyline(xy(p0), xy(p1), line) || crosses_polyline(xy(p1), xy(p2), line) ||
           crosses_polyline(xy(p2), xy(p0), line);
  };
  // A hinge goes with either of its triangles.
  const Hinges& h = m.sheet.model.hinges;
  std::vector<bool> keep_hinge(h.size(), true);
  for (int e = 0; e < h.size(); ++e) {
    const auto& v = h.v[e];
    keep_hinge[e] = !cut_triangle(v[0], v[1], v[2]) && !cut_triangle(v[1], v[0], v[3]);
  }
  filter_hinges(m, keep_hinge);

  auto& tris = m.sheet.triangles;
  std::erase_if(tris, [&](const Triangle& t) { return cut_triangle(t[0], t[1], t[2]); });
  return removed;
}

namespace {

// The sheet rebuilt on the nodes outside the hole (the new edge carries half stiffness), its
// particles carrying the old ones' state, pins and process state.
Membrane rebuild_without(const Membrane& m, const std::vector<bool>& keep_node,
                         std::vector<int>& new_of_old) {
  const GridSheet& g = m.sheet.grid;
  const Model& old = m.sheet.model;
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
  Model& nm = n.sheet.model;
  new_of_old.assign(static_cast<size_t>(old.num_particles()), -1);
  for (int p = 0; p < nm.num_particles(); ++p) {
    const auto [i, j] = ng.node(p);
    const int op = g.particle(i, j);
    new_of_old[op] = p;
    n.state.x.col(p) = m.state.x.col(op);
    n.state.v.col(p) = m.state.v.col(op);
    if (old.pinned(op)) nm.pin(p);
  }
  n.state.time = m.state.time;
  nm.gravity = old.gravity;
  nm.velocity_damping = old.velocity_damping;
  for (int p : m.frame)
    if (new_of_old[p] >= 0) n.frame.push_back(new_of_old[p]);
  n.stretch = m.stretch;
  n.resin_side = m.resin_side;
  n.impregnated = m.impregnated;
  n.coats = m.coats;
  n.releasing = m.releasing;
  n.release_level = m.release_level;
  return n;
}

// Lattice springs: the rebuilt stiffness, the old process state; springs an earlier cut removed
// stay removed. Added springs whose ends survive come along.
void carry_springs(const Membrane& m, const std::vector<int>& new_of_old, Membrane& n) {
  const GridSheet& g = m.sheet.grid;
  const GridSheet& ng = n.sheet.grid;
  const Springs& os = m.sheet.model.springs;
  std::map<SpringKey, int> old_spring;
  for (int s = 0; s < os.size(); ++s)
    if (os.family[s] != SpringFamily::added) old_spring[spring_key(g, os, s)] = s;
  Springs& ns = n.sheet.model.springs;
  std::vector<bool> keep(ns.size(), false);
  for (int s = 0; s < ns.size(); ++s) {
    const auto it = old_spring.find(spring_key(ng, ns, s));
    if (it == old_spring.end()) continue;
    const int o = it->second;
    keep[s] = true;
    n.natural_length[s] = m.natural_length[o];
    n.frame_length[s] = m.frame_length[o];
    n.resin_fraction[s] = m.resin_fraction[o];
    n.resin_length[s] = m.resin_length[o];
    n.resin_stiffness[s] = m.resin_stiffness[o] * n.latex_stiffness[s] / m.latex_stiffness[o];
  }
  filter_springs(n, keep);
  for (int s = 0; s < os.size(); ++s) {
    if (os.family[s] != SpringFamily::added) continue;
    const int a = new_of_old[os.a[s]], b = new_of_old[os.b[s]];
    if (a < 0 || b < 0) continue;
    ns.add(a, b, os.rest_length[s], os.stiffness[s], os.damping[s], SpringFamily::added,
           os.width[s]);
    n.natural_length.push_back(m.natural_length[s]);
    n.latex_stiffness.push_back(m.latex_stiffness[s]);
    n.resin_fraction.push_back(0.0);
    n.resin_stiffness.push_back(0.0);
    n.resin_length.push_back(m.resin_length[s]);
    n.frame_length.push_back(m.frame_length[s]);
  }
}

// Bending elements and triangles: those that still exist, with their resin.
void carry_bending(const Membrane& m, Membrane& n) {
  const GridSheet& g = m.sheet.grid;
  const GridSheet& ng = n.sheet.grid;
  const Model& old = m.sheet.model;
  std::map<BendKey, int> old_bend;
  for (int e = 0; e < old.bending.size(); ++e) {
    const auto& v = old.bending.v[e];
    old_bend[{node_id(g, v[0]), node_id(g, v[1]), node_id(g, v[2])}] = e;
  }
  Bending& nb = n.sheet.model.bending;
  std::vector<bool> keep_bend(nb.size(), false);
  for (int e = 0; e < nb.size(); ++e) {
    const auto& v = nb.v[e];
    const auto it = old_bend.find({node_id(ng, v[0]), node_id(ng, v[1]), node_id(ng, v[2])});
    if (it == old_bend.end()) continue;
    const int o = it->second;
    keep_bend[e] = true;
    n.bending_fraction[e] = m.bending_fraction[o];
    n.resin_bending[e] = m.resin_bending[o] * nb.factor[e] / old.bending.factor[o];
    nb.stiffness[e] =
        composite_bending(n.latex_bending[e], n.resin_bending[e], n.bending_fraction[e]);
  }
  filter_bending(n, keep_bend);
  std::map<TriKey, bool> old_tri;
  for (const Triangle& t : m.sheet.triangles) old_tri[tri_key(g, t)] = true;
  std::erase_if(n.sheet.triangles,
                [&](const Triangle& t) { return !old_tri.contains(tri_key(ng, t)); });
}

// Hinges whose four particles and two triangles survive, with their moments.
void carry_hinges(const Membrane& m, const std::vector<int>& new_of_old, Membrane& n) {
  const GridSheet& ng = n.sheet.grid;
  const Model& old = m.sheet.model;
  std::map<TriKey, bool> new_tri;
  for (const Triangle& t : n.sheet.triangles) new_tri[tri_key(ng, t)] = true;
  for (int e = 0; e < old.hinges.size(); ++e) {
    std::array<int, 4> v;
    bool alive = true;
    for (int k = 0; k < 4; ++k) {
      v[static_cast<size_t>(k)] = new_of_old[old.hinges.v[e][static_cast<size_t>(k)]];
      alive = alive && v[static_cast<size_t>(k)] >= 0;
    }
    alive = alive && new_tri.contains(tri_key(ng, Triangle(v[0], v[1], v[2]))) &&
            new_tri.contains(tri_key(ng, Triangle(v[1], v[0], v[3])));
    if (!alive) continue;
    n.sheet.model.hinges.add(v, old.hinges.moment[e]);
    n.hinge_full_moment.push_back(m.hinge_full_moment[e]);
    n.hinge_coverage.push_back(m.hinge_coverage[e]);
  }
}

}  // namespace

int punch_hole(Membrane& m, const Pattern& hole, std::vector<Vec2>* where) {
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
  carry_springs(m, new_of_old, n);
  carry_bending(m, n);
  carry_hinges(m, new_of_old, n);
  for (int s = 0; s < n.sheet.model.springs.size(); ++s) update_spring(n, s);
  const int removed = old.num_particles() - n.sheet.model.num_particles();
  m = std::move(n);
  return removed;
}

}  // namespace membra
