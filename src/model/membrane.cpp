#include "membra/model/membrane.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "membra/model/bilayer.hpp"

namespace membra {

Membrane make_membrane(Sheet sheet) {
  Membrane m;
  m.sheet = std::move(sheet);
  m.state = State::at_rest(m.sheet.model);
  const Springs& s = m.sheet.model.springs;
  m.natural_length = s.rest_length;
  m.latex_stiffness = s.stiffness;
  m.resin_fraction.assign(s.rest_length.size(), 0.0);
  m.resin_stiffness.assign(s.rest_length.size(), 0.0);
  m.resin_length = s.rest_length;
  m.frame_length = s.rest_length;
  const Bending& b = m.sheet.model.bending;
  m.latex_bending = b.stiffness;
  m.resin_bending.assign(b.stiffness.size(), 0.0);
  m.bending_fraction.assign(b.stiffness.size(), 0.0);
  return m;
}

int stretch_frame(Membrane& m, double lx, double ly, FrameEdges edges) {
  if (!(lx > 0.0) || !(ly > 0.0)) throw std::invalid_argument("stretch ratios must be > 0");
  m.state.x.row(0) *= lx;
  m.state.x.row(1) *= ly;
  m.state.v.setZero();
  m.stretch = m.stretch.cwiseProduct(Vec2(lx, ly));
  m.impregnated.clear();  // the sheet moves under the earlier patterns
  m.coats.clear();
  const GridSheet& g = m.sheet.grid;
  Model& model = m.sheet.model;
  // The frame holds the sheet's outer rim: the first and last node of every row (left, right)
  // and of every column (bottom, top). On a rectangle these are its four edges; on a disk, the
  // nodes along its circle; the rims of holes inside the sheet are not held.
  std::vector<int> row_lo(static_cast<size_t>(g.ny()), g.nx()), row_hi(row_lo.size(), -1);
  std::vector<int> col_lo(static_cast<size_t>(g.nx()), g.ny()), col_hi(col_lo.size(), -1);
  for (int p = 0; p < model.num_particles(); ++p) {
    const auto [i, j] = g.node(p);
    const auto ui = static_cast<size_t>(i), uj = static_cast<size_t>(j);
    row_lo[uj] = std::min(row_lo[uj], i), row_hi[uj] = std::max(row_hi[uj], i);
    col_lo[ui] = std::min(col_lo[ui], j), col_hi[ui] = std::max(col_hi[ui], j);
  }
  for (int p = 0; p < model.num_particles(); ++p) {
    const auto [i, j] = g.node(p);
    const auto ui = static_cast<size_t>(i), uj = static_cast<size_t>(j);
    const bool held = (edges.left && i == row_lo[uj]) || (edges.right && i == row_hi[uj]) ||
                      (edges.bottom && j == col_lo[ui]) || (edges.top && j == col_hi[ui]);
    if (!held) continue;
    if (model.pinned(p)) continue;  // already held (a user pin or the frame)
    model.pin(p);
    m.frame.push_back(p);
  }
  return static_cast<int>(m.frame.size());
}

void update_spring(Membrane& m, int s) {
  Springs& sp = m.sheet.model.springs;
  if (sp.family[s] == SpringFamily::added) {  // added springs keep what add_springs gave them
    sp.rest_length[s] = m.natural_length[s];
    sp.stiffness[s] = m.latex_stiffness[s];
    return;
  }
  const double l_nat = m.natural_length[s];
  const double latex_rest =
      m.releasing ? l_nat + m.release_level * (m.frame_length[s] - l_nat) : l_nat;
  const double f = m.resin_fraction[s], kl = m.latex_stiffness[s];
  if (f <= 0.0) {
    sp.rest_length[s] = latex_rest;
    sp.stiffness[s] = kl;
    return;
  }
  // Resin part: resin and latex in parallel (the resin soaks the latex), the resin at rest at
  // its impregnation length. Along the spring, the resin and latex parts act in series.
  const double k_in = m.resin_stiffness[s] + kl;
  const double rest_in = (m.resin_stiffness[s] * m.resin_length[s] + kl * latex_rest) / k_in;
  sp.stiffness[s] = 1.0 / ((1.0 - f) / kl + f / k_in);
  sp.rest_length[s] = (1.0 - f) * latex_rest + f * rest_in;
}

int impregnate(Membrane& m, const PatternPtr& pattern_ptr, const Material& resin, int side,
               bool bilayer) {
  const Pattern& pattern = *pattern_ptr;
  // Fractions of the union with earlier patterns, so that two patterns meeting edge to edge
  // leave no weaker seam (the springs and elements they share are whole resin).
  m.impregnated.push_back(pattern_ptr);
  const PatternPtr all = make_union(m.impregnated);
  // (Never less than before: resin cured in an earlier state stays.)
  Model& model = m.sheet.model;
  const Points& x = m.state.x;
  const LatticeStiffness kr = homogenize(
      resin,
      m.sheet.stiffness.flex > 0.0 ? m.sheet.stiffness.flex / m.sheet.stiffness.stretch : 0.0);
  int count = 0;
  Springs& sp = model.springs;
  for (int s = 0; s < sp.size(); ++s) {
    if (sp.family[s] == SpringFamily::added) continue;  // not part of the sheet
    if (fraction_inside(pattern, x.col(sp.a[s]).head<2>(), x.col(sp.b[s]).head<2>()) <= 0.0)
      continue;
    ++count;
    m.resin_fraction[s] =
        std::max(m.resin_fraction[s],
                 fraction_inside(*all, x.col(sp.a[s]).head<2>(), x.col(sp.b[s]).head<2>()));
    m.resin_length[s] = (x.col(sp.b[s]) - x.col(sp.a[s])).norm();
    // Same family and the same share of a cell as the latex spring (half on the boundary).
    const LatticeStiffness& kl = m.sheet.stiffness;
    const bool shear = sp.family[s] == SpringFamily::shear;
    const bool flex = sp.family[s] == SpringFamily::flex;
    const double share = m.latex_stiffness[s] / (shear ? kl.shear : flex ? kl.flex : kl.stretch);
    m.resin_stiffness[s] = share * (shear ? kr.shear : flex ? kr.flex : kr.stretch);
    update_spring(m, s);
  }
  Bending& b = model.bending;
  const double d_resin = bending_stiffness(resin);
  const GridSheet& g = m.sheet.grid;
  const double hx_now = g.hx() * m.stretch.x(), hy_now = g.hy() * m.stretch.y();
  for (int e = 0; e < b.size(); ++e) {
    const auto& v = b.v[e];
    const auto share = [&](const Pattern& p) {
      return 0.5 * (fraction_inside(p, x.col(v[0]).head<2>(), x.col(v[1]).head<2>(), 8) +
                    fraction_inside(p, x.col(v[1]).head<2>(), x.col(v[2]).head<2>(), 8));
    };
    if (share(pattern) <= 0.0) continue;
    m.bending_fraction[e] = std::max(m.bending_fraction[e], share(*all));
    // The resin plate forms in the stretched sheet, whose cells are hx' x hy': its elements
    // take the plate weights of those cells.
    const Vec3 span = model.reference.col(v[2]) - model.reference.col(v[0]);
    const auto [ni, nj] = g.node(v[1]);
    const int di = span.x() > 0 ? 1 : span.x() < 0 ? -1 : 0;
    const int dj = span.y() > 0 ? 1 : span.y() < 0 ? -1 : 0;
    m.resin_bending[e] = d_resin * bending_factor(g, ni, nj, di, dj, hx_now, hy_now);
    const double cl = m.latex_bending[e], fe = m.bending_fraction[e];
    b.stiffness[e] = 1.0 / ((1.0 - fe) / cl + fe / (cl + m.resin_bending[e]));
  }
  m.resin_side = side >= 0 ? 1 : -1;
  if (bilayer) {
    m.coats.push_back(pattern_ptr);
    const PatternPtr coats = make_union(m.coats);
    add_bilayer_hinges(m, pattern, resin, m.resin_side, coats.get());
  }
  return count;
}

void begin_release(Membrane& m) {
  Model& model = m.sheet.model;
  for (int p : m.frame) model.unpin(p);
  m.frame.clear();
  m.impregnated.clear();
  m.coats.clear();
  const Springs& sp = model.springs;
  for (int s = 0; s < sp.size(); ++s)
    m.frame_length[s] = (m.state.x.col(sp.b[s]) - m.state.x.col(sp.a[s])).norm();
  m.releasing = true;
  set_release_level(m, 1.0);
}

void set_release_level(Membrane& m, double level) {
  m.release_level = std::clamp(level, 0.0, 1.0);
  for (int s = 0; s < m.sheet.model.springs.size(); ++s) update_spring(m, s);
  update_hinge_moments(m);
}

void perturb(Membrane& m, double amplitude, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  const GridSheet& g = m.sheet.grid;
  for (int p = 0; p < m.sheet.model.num_particles(); ++p) {
    if (m.sheet.model.pinned(p)) continue;
    const auto [i, j] = g.node(p);
    const double u = static_cast<double>(i) / (g.nx() - 1),
                 v = static_cast<double>(j) / (g.ny() - 1);
    const double bump = std::sin(std::numbers::pi * u) * std::sin(std::numbers::pi * v);
    m.state.x(2, p) += amplitude * (m.resin_side * bump + 0.1 * noise(rng));
  }
}

void perturb_randomly(Membrane& m, double amplitude, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  double c[3][3];  // weights of sin(a pi u) sin(b pi v), lower modes likelier
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) c[a][b] = gauss(rng) / ((a + 1) * (b + 1));
  const GridSheet& g = m.sheet.grid;
  const int n = m.sheet.model.num_particles();
  std::vector<double> w(static_cast<size_t>(n), 0.0);
  double peak = 0.0;
  for (int p = 0; p < n; ++p) {
    const auto [i, j] = g.node(p);
    const double u = static_cast<double>(i) / (g.nx() - 1),
                 v = static_cast<double>(j) / (g.ny() - 1);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        w[p] += c[a][b] * std::sin((a + 1) * std::numbers::pi * u) *
                std::sin((b + 1) * std::numbers::pi * v);
    peak = std::max(peak, std::abs(w[p]));
  }
  if (peak == 0.0) peak = 1.0;
  for (int p = 0; p < n; ++p) {
    if (m.sheet.model.pinned(p)) continue;
    m.state.x(2, p) += amplitude * (w[p] / peak + 0.1 * noise(rng));
  }
}

}  // namespace membra
