#include "membra/model/membrane.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace membra {

Membrane make_membrane(Sheet sheet) {
  Membrane m;
  m.sheet = std::move(sheet);
  m.state = State::at_rest(m.sheet.model);
  m.sheet.model.springs.reset_material();
  m.sheet.model.bending.reset_material();
  return m;
}

void carry_process_state(const Membrane& from, const std::vector<int>& new_of_old, Membrane& to) {
  const Model& old = from.sheet.model;
  Model& nm = to.sheet.model;
  for (int op = 0; op < old.num_particles(); ++op) {
    const int p = new_of_old[static_cast<size_t>(op)];
    if (p < 0) continue;
    to.state.x.col(p) = from.state.x.col(op);
    to.state.v.col(p) = from.state.v.col(op);
    if (old.pinned(op)) nm.pin(p);
  }
  to.state.time = from.state.time;
  nm.gravity = old.gravity;
  nm.velocity_damping = old.velocity_damping;
  to.frame.clear();
  for (int p : from.frame)
    if (new_of_old[static_cast<size_t>(p)] >= 0)
      to.frame.push_back(new_of_old[static_cast<size_t>(p)]);
  to.stretch = from.stretch;
  to.resin_side = from.resin_side;
  to.impregnated = from.impregnated;
  to.coats = from.coats;
  to.releasing = from.releasing;
  to.release_level = from.release_level;
}

namespace {

// The continuum sheet's frame: the rim particles whose outward normal points towards a held
// edge (on a disk, as on the lattice, left and right hold every rim particle but the top and
// bottom ones).
int hold_rim(Membrane& m, FrameEdges edges) {
  const SheetMesh& mesh = m.sheet.mesh;
  Model& model = m.sheet.model;
  constexpr double eps = 1e-6;
  for (size_t k = 0; k < mesh.rim.size(); ++k) {
    const Vec2& n = mesh.rim_normal[k];
    const bool held = (edges.left && n.x() < -eps) || (edges.right && n.x() > eps) ||
                      (edges.bottom && n.y() < -eps) || (edges.top && n.y() > eps);
    const int p = mesh.rim[k];
    if (!held || model.pinned(p)) continue;
    model.pin(p);
    m.frame.push_back(p);
  }
  return static_cast<int>(m.frame.size());
}

// Where particle p lies on the sheet, as fractions (u, v) of its width and height: grid nodes
// by their indices, mesh vertices by their paper positions.
Vec2 unit_position(const Sheet& sheet, int p) {
  const GridSheet& g = sheet.grid;
  if (sheet.continuum()) {
    const Vec2 q = sheet.model.reference.col(p).head<2>();
    return {q.x() / g.width(), q.y() / g.height()};
  }
  const auto [i, j] = g.node(p);
  return {static_cast<double>(i) / (g.nx() - 1), static_cast<double>(j) / (g.ny() - 1)};
}

}  // namespace

int stretch_frame(Membrane& m, double lx, double ly, FrameEdges edges) {
  if (!(lx > 0.0) || !(ly > 0.0)) throw std::invalid_argument("stretch ratios must be > 0");
  m.state.x.row(0) *= lx;
  m.state.x.row(1) *= ly;
  m.state.v.setZero();
  m.stretch = m.stretch.cwiseProduct(Vec2(lx, ly));
  m.impregnated.clear();  // the sheet moves under the earlier patterns
  m.coats.clear();
  if (m.sheet.continuum()) return hold_rim(m, edges);
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

void update_elements(Membrane& m) {
  m.sheet.model.for_each_set([&](auto& set) { set.update(m.release()); });
}

int impregnate(Membrane& m, const PatternPtr& pattern_ptr, const Material& resin, int side,
               bool bilayer) {
  // Fractions of the union with earlier patterns, so that two patterns meeting edge to edge
  // leave no weaker seam (the elements they share are whole resin).
  m.impregnated.push_back(pattern_ptr);
  const PatternPtr all = make_union(m.impregnated);
  m.resin_side = side >= 0 ? 1 : -1;
  if (bilayer) m.coats.push_back(pattern_ptr);
  const PatternPtr coats = bilayer ? make_union(m.coats) : nullptr;
  const Impregnation at{*pattern_ptr, *all,  coats.get(),  m.sheet, m.state.x,
                        m.stretch,    resin, m.resin_side, bilayer, m.release()};
  // Each set's resin rule; the count is of the elements that carry the sheet's stretch.
  int count = 0;
  m.sheet.model.for_each_set([&](auto& set) {
    const int n = set.impregnate(at);
    if (set.kEnergy == EnergyKind::stretching) count += n;
  });
  return count;
}

void begin_release(Membrane& m) {
  Model& model = m.sheet.model;
  for (int p : m.frame) model.unpin(p);
  m.frame.clear();
  m.impregnated.clear();
  m.coats.clear();
  model.for_each_set([&](auto& set) { set.begin_release(m.state.x); });
  m.releasing = true;
  set_release_level(m, 1.0);
}

void set_release_level(Membrane& m, double level) {
  m.release_level = std::clamp(level, 0.0, 1.0);
  update_elements(m);
}

void perturb(Membrane& m, double amplitude, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  for (int p = 0; p < m.sheet.model.num_particles(); ++p) {
    if (m.sheet.model.pinned(p)) continue;
    const Vec2 uv = unit_position(m.sheet, p);
    const double u = uv.x(), v = uv.y();
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
  const int n = m.sheet.model.num_particles();
  std::vector<double> w(static_cast<size_t>(n), 0.0);
  double peak = 0.0;
  for (int p = 0; p < n; ++p) {
    const Vec2 uv = unit_position(m.sheet, p);
    const double u = uv.x(), v = uv.y();
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
