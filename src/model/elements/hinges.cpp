#include "membra/model/elements/hinges.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "membra/model/bilayer.hpp"
#include "membra/model/elements/hinge_kernel.hpp"
#include "membra/model/pattern.hpp"
#include "membra/model/sheet.hpp"

namespace membra {

static_assert(ElementSet<Hinges>);

namespace {

using Mat2 = Eigen::Matrix2d;
constexpr double kNu = 1.0 / 3.0;  // the lattice's Poisson ratio (material.hpp)

// Each directed edge of a (counter-clockwise) triangle, with the vertex to its left.
struct Half {
  int tri, opposite;
};
std::map<std::pair<int, int>, Half> half_edges(const std::vector<Triangle>& tris) {
  std::map<std::pair<int, int>, Half> half;
  for (int t = 0; t < static_cast<int>(tris.size()); ++t)
    for (int k = 0; k < 3; ++k)
      half[{tris[t][k], tris[t][(k + 1) % 3]}] = {t, tris[t][(k + 2) % 3]};
  return half;
}

// A hinge's moment per unit plate stiffness for the spontaneous curvature k0: the moment tensor
// of the plate energy's linear term, D [(1 - nu) k0 + nu tr(k0) I]; a hinge across an edge of
// in-plane vector e takes p^T M p / |e| with p = e turned by 90 degrees, which sums to the
// integral of M : k over a regular triangulation (docs/process.md).
double unit_moment(const Mat2& k0, const Eigen::Vector2d& e) {
  const Mat2 mt = (1.0 - kNu) * k0 + kNu * k0.trace() * Mat2::Identity();
  const Eigen::Vector2d p(-e.y(), e.x());
  return p.dot(mt * p) / e.norm();
}

using TriKey = std::array<int, 3>;
TriKey sorted(TriKey k) {
  std::sort(k.begin(), k.end());
  return k;
}

}  // namespace

void Hinges::add(const std::array<int, 4>& h, double m, double full, double covered) {
  v.push_back(h);
  moment.push_back(m);
  full_moment.push_back(full);
  coverage.push_back(covered);
}

void Hinges::filter(const std::vector<bool>& keep) {
  keep_where(v, keep);
  keep_where(moment, keep);
  keep_where(full_moment, keep);
  keep_where(coverage, keep);
}

double Hinges::energy(int i, const Points& x) const {
  const auto& e = v[static_cast<size_t>(i)];
  return moment[i] * hinge_eval(x.col(e[0]), x.col(e[1]), x.col(e[2]), x.col(e[3])).theta;
}

void Hinges::add_forces(const Points& x, const Points*, int begin, int end, Points& f) const {
  for (int i = begin; i < end; ++i) {
    const double m = moment[i];
    if (m == 0.0) continue;
    const auto& e = v[static_cast<size_t>(i)];
    const HingeEval r = hinge_eval(x.col(e[0]), x.col(e[1]), x.col(e[2]), x.col(e[3]));
    for (int k = 0; k < 4; ++k) f.col(e[k]) -= m * r.grad[k];
  }
}

Eigen::Matrix<double, 12, 12> Hinges::hessian(int i, const Points& x, bool project) const {
  const auto& e = v[static_cast<size_t>(i)];
  return hinge_hessian(x.col(e[0]), x.col(e[1]), x.col(e[2]), x.col(e[3]), moment[i], project);
}

void Hinges::update(const ReleaseLevel& release) {
  const double share = release.releasing ? 1.0 - release.level : 0.0;
  for (int e = 0; e < size(); ++e) moment[e] = share * full_moment[static_cast<size_t>(e)];
}

bool Hinges::severed(int i, const CrossesCut& crosses) const {
  const auto& e = v[static_cast<size_t>(i)];
  auto cut_triangle = [&](int p0, int p1, int p2) {
    return crosses(p0, p1) || crosses(p1, p2) || crosses(p2, p0);
  };
  return cut_triangle(e[0], e[1], e[2]) || cut_triangle(e[1], e[0], e[3]);
}

int Hinges::impregnate(const Impregnation& at) {
  // A continuum sheet's shell triangles carry a coat's curvature themselves.
  if (!at.bilayer || at.sheet.continuum()) return 0;
  const Sheet& sheet = at.sheet;
  const Points& x = at.x;
  const double per_strain = bilayer_curvature_per_strain(sheet.material, at.resin);
  const double d_latex = bending_stiffness(sheet.material);
  const double d = d_latex + bending_stiffness(at.resin);
  const double sign = at.side >= 0 ? 1.0 : -1.0;
  const auto& tris = sheet.triangles;
  const auto half = half_edges(tris);
  std::map<std::pair<int, int>, int> existing;
  for (int e = 0; e < size(); ++e) existing[{v[e][0], v[e][1]}] = e;
  // A hinge partly inside the coat takes the share f of its spontaneous curvature, and its
  // moment is that curvature times the stiffness the bending elements there have: the coat and
  // the bare latex beside it in series, as the bending elements' composite rule combines them.
  // With the coat's full stiffness instead, a coat's edge would carry the moment of the coat
  // against the bending stiffness of the latex (a thousandth of it) and crease.
  const auto d_edge = [&](double share) { return 1.0 / ((1.0 - share) / d_latex + share / d); };
  int count = 0;
  for (const auto& [edge, left] : half) {
    const auto [a, b] = edge;
    if (a > b) continue;  // each interior edge once
    const auto right = half.find({b, a});
    if (right == half.end()) continue;  // a boundary edge has no hinge
    const int c = left.opposite, dd = right->second.opposite;
    const auto it = existing.find({a, b});
    const size_t old = it != existing.end() ? static_cast<size_t>(it->second) : 0;
    // Coats on both sides of a hinge (two steps meeting there) add up to its whole, overlaps
    // counted once; where a coat lies already, the first one stays.
    const double covered = it != existing.end() ? coverage[old] : 0.0;
    const Vec2 pc = x.col(c).head<2>(), pd = x.col(dd).head<2>();
    const double own = fraction_inside(at.pattern, pc, pd, 8);
    if (own <= 0.0) continue;
    const double f =
        std::min(own, (at.coats ? fraction_inside(*at.coats, pc, pd, 8) : 1.0) - covered);
    if (f <= 1e-12) continue;
    const Triangle& t1 = tris[left.tri];
    const Triangle& t2 = tris[right->second.tri];
    const Points& ref = sheet.model.reference;
    const Mat2 fg = 0.5 * (in_plane_gradient(ref, x, t1[0], t1[1], t1[2]) +
                           in_plane_gradient(ref, x, t2[0], t2[1], t2[2]));
    const Eigen::Vector2d ev = (x.col(b) - x.col(a)).head<2>();
    if (!(ev.norm() > 0.0)) continue;
    const double full =
        sign * unit_moment(f * per_strain * misfit_strain(fg), ev) * d_edge(covered + f);
    if (it != existing.end()) {
      // The earlier coats' curvature at the stiffness of all the coats on this hinge.
      const double before = full_moment[old] / d_edge(covered);
      full_moment[old] = before * d_edge(covered + f) + full;
      coverage[old] += f;
    } else {
      add({a, b, c, dd}, 0.0, full, f);
    }
    ++count;
  }
  update(at.release);
  return count;
}

void Hinges::carry(const Hinges& old, const Rebuild& r) {
  if (old.size() == 0) return;  // nothing to carry (and a continuum sheet has no grid to read)
  const GridSheet& ng = r.new_sheet.grid;
  auto node_id = [&](int p) {
    const auto [i, j] = ng.node(p);
    return j * ng.nx() + i;
  };
  std::set<TriKey> new_tri;
  for (const Triangle& t : r.new_sheet.triangles)
    new_tri.insert(sorted({node_id(t[0]), node_id(t[1]), node_id(t[2])}));
  auto alive_triangle = [&](int a, int b, int c) {
    return new_tri.contains(sorted({node_id(a), node_id(b), node_id(c)}));
  };
  for (int e = 0; e < old.size(); ++e) {
    std::array<int, 4> p;
    if (r.map(old.v[static_cast<size_t>(e)], p) && alive_triangle(p[0], p[1], p[2]) &&
        alive_triangle(p[1], p[0], p[3]))
      add(p, old.moment[e], old.full_moment[e], old.coverage[e]);
  }
}

}  // namespace membra
