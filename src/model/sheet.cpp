#include "membra/model/sheet.hpp"

#include <cmath>
#include <stdexcept>

namespace membra {
namespace {

LatticeStiffness lattice_stiffness(const SheetOptions& o) {
  const double ratio = o.flex ? o.flex_ratio : 0.0;
  LatticeStiffness k = homogenize(o.material, ratio);
  if (o.stretch_stiffness) {
    // The paper's K sets the stretch springs; the others keep their isotropic ratios.
    const double scale = *o.stretch_stiffness / k.stretch;
    k.stretch *= scale;
    k.shear *= scale;
    k.flex *= scale;
  }
  return k;
}

// Active cells among those touching node (i, j) (0..4).
int cells_around(const GridSheet& g, int i, int j) {
  return g.cell_active(i - 1, j - 1) + g.cell_active(i, j - 1) + g.cell_active(i - 1, j) +
         g.cell_active(i, j);
}

constexpr int kBendDirections[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};

void add_lattice_springs(const GridSheet& g, const SheetOptions& o, const LatticeStiffness& k,
                         Model& m) {
  // Tributary width: the spacing between parallel springs of the family (h for grid lines, h/sqrt2
  // for diagonals), scaled like the stiffness on the boundary.
  const double h = g.hx();
  auto connect = [&](int pa, int pb, double kk, SpringFamily fam) {
    const double l0 = (m.reference.col(pb) - m.reference.col(pa)).norm();
    const double full = fam == SpringFamily::stretch ? k.stretch
                        : fam == SpringFamily::shear ? k.shear
                                                     : k.flex;
    const double spacing = fam == SpringFamily::shear ? h / std::sqrt(2.0) : h;
    m.springs.add(pa, pb, l0, kk, o.spring_damping, fam, full > 0.0 ? spacing * kk / full : 0.0);
  };
  for (int j = 0; j < g.ny(); ++j) {
    for (int i = 0; i < g.nx(); ++i) {
      const int p = g.particle(i, j);
      if (p < 0) continue;
      if (o.stretch) {
        // An edge carries the membrane of the cells beside it: half a cell's worth on the
        // boundary, so the sheet's stiffness is k per unit width up to its edges.
        const int right = g.cell_active(i, j - 1) + g.cell_active(i, j);
        const int up = g.cell_active(i - 1, j) + g.cell_active(i, j);
        if (const int q = g.particle(i + 1, j); q >= 0 && right > 0)
          connect(p, q, 0.5 * right * k.stretch, SpringFamily::stretch);
        if (const int q = g.particle(i, j + 1); q >= 0 && up > 0)
          connect(p, q, 0.5 * up * k.stretch, SpringFamily::stretch);
      }
      if (o.shear && g.cell_active(i, j)) {
        connect(p, g.particle(i + 1, j + 1), k.shear, SpringFamily::shear);
        connect(g.particle(i + 1, j), g.particle(i, j + 1), k.shear, SpringFamily::shear);
      }
      if (o.flex) {
        if (g.particle(i + 1, j) >= 0 && g.particle(i + 2, j) >= 0)
          connect(p, g.particle(i + 2, j), 0.25 * cells_around(g, i + 1, j) * k.flex,
                  SpringFamily::flex);
        if (g.particle(i, j + 1) >= 0 && g.particle(i, j + 2) >= 0)
          connect(p, g.particle(i, j + 2), 0.25 * cells_around(g, i, j + 1) * k.flex,
                  SpringFamily::flex);
      }
    }
  }
}

// Elements centred on every node with both neighbours present, along x, y and both diagonals.
void add_bending_elements(const GridSheet& g, double d, Bending& out) {
  for (int j = 0; j < g.ny(); ++j)
    for (int i = 0; i < g.nx(); ++i) {
      const int p = g.particle(i, j);
      if (p < 0) continue;
      for (const auto& dir : kBendDirections) {
        const int a = g.particle(i - dir[0], j - dir[1]), b = g.particle(i + dir[0], j + dir[1]);
        if (a < 0 || b < 0) continue;
        const double factor = bending_factor(g, i, j, dir[0], dir[1], g.hx(), g.hy());
        out.add(a, p, b, factor * d, factor);
      }
    }
}

}  // namespace

double bending_factor(const GridSheet& g, int i, int j, int di, int dj, double hx, double hy) {
  auto present = [&](int dx, int dy) {
    return g.particle(i - dx, j - dy) >= 0 && g.particle(i + dx, j + dy) >= 0;
  };
  if (g.particle(i, j) < 0 || !present(di, dj)) return 0.0;
  const PlateWeights w = plate_bending_weights(hx, hy);
  const double area = 0.25 * cells_around(g, i, j);  // a boundary node has less area
  if (di != 0 && dj != 0) return w.diagonal * area;
  // A missing diagonal (a node on an edge) hands its share of the curvature along this axis to
  // the axis element, so the edge bends like the plate with no curvature across it.
  const double l2 = hx * hx + hy * hy;
  double weight = di != 0 ? w.x : w.y;
  for (int s : {1, -1})
    if (!present(1, s)) weight += w.diagonal * (di != 0 ? hx * hx : hy * hy) / l2;
  return weight * area;
}

Sheet build_sheet(const GridSpec& spec, const SheetOptions& o, const NodeMask& keep) {
  const Material& mat = o.material;
  if (!(mat.youngs_modulus > 0.0) || !(mat.thickness > 0.0) || !(mat.density > 0.0))
    throw std::invalid_argument("sheet material: E, thickness and density must be positive");
  if (o.stretch_stiffness && !(*o.stretch_stiffness > 0.0))
    throw std::invalid_argument("sheet: stretch stiffness K must be positive");
  GridSheet grid = GridSheet(spec, keep).without_isolated_nodes();
  if (grid.num_particles() == 0) throw std::invalid_argument("sheet: the mask removes every cell");

  Model m;
  const int n = grid.num_particles();
  m.mass.assign(n, 0.0);
  m.reference = Points::Zero(3, n);
  for (int p = 0; p < n; ++p) {
    const auto [i, j] = grid.node(p);
    m.reference.col(p).head<2>() = grid.position(i, j);
  }
  const double cell_mass = grid.hx() * grid.hy() * mat.thickness * mat.density;
  for (int j = 0; j + 1 < grid.ny(); ++j)
    for (int i = 0; i + 1 < grid.nx(); ++i)
      if (grid.cell_active(i, j))
        for (int p : {grid.particle(i, j), grid.particle(i + 1, j), grid.particle(i, j + 1),
                      grid.particle(i + 1, j + 1)})
          m.mass[p] += 0.25 * cell_mass;
  m.inv_mass.resize(n);
  for (int p = 0; p < n; ++p) m.inv_mass[p] = 1.0 / m.mass[p];

  const LatticeStiffness k = lattice_stiffness(o);
  add_lattice_springs(grid, o, k, m);
  std::vector<Triangle> tris = triangulate(grid);
  if (o.bending) add_bending_elements(grid, bending_stiffness(mat), m.bending);
  return Sheet{std::move(grid), mat, std::move(m), std::move(tris), k, o, {}};
}

}  // namespace membra
