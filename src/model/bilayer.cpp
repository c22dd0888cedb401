#include "membra/model/bilayer.hpp"

#include <algorithm>

#include <Eigen/Eigenvalues>
#include <map>
#include <stdexcept>

namespace membra {
namespace {

using Mat2 = Eigen::Matrix2d;
constexpr double kNu = 1.0 / 3.0;  // the lattice's Poisson ratio (material.hpp)

// In-plane deformation gradient of triangle (a, b, c) from paper to current coordinates.
Mat2 deformation(const Model& model, const Points& x, int a, int b, int c) {
  Mat2 r, q;
  r.col(0) = (model.reference.col(b) - model.reference.col(a)).head<2>();
  r.col(1) = (model.reference.col(c) - model.reference.col(a)).head<2>();
  q.col(0) = (x.col(b) - x.col(a)).head<2>();
  q.col(1) = (x.col(c) - x.col(a)).head<2>();
  return q * r.inverse();
}

// eps = I - V^-1 with V = sqrt(F F^T): the strain by which the latex, bonded to resin at rest
// in the current state, would shorten along each direction if it were free.
Mat2 misfit_strain(const Mat2& f) {
  const Eigen::SelfAdjointEigenSolver<Mat2> eig(f * f.transpose());
  const Eigen::Vector2d inv_stretch = eig.eigenvalues().cwiseMax(1e-12).cwiseSqrt().cwiseInverse();
  return Mat2::Identity() -
         eig.eigenvectors() * inv_stretch.asDiagonal() * eig.eigenvectors().transpose();
}

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

}  // namespace

double bilayer_curvature_per_strain(const Material& base, const Material& layer) {
  if (!(base.thickness > 0.0) || !(layer.thickness > 0.0) || !(base.youngs_modulus > 0.0) ||
      !(layer.youngs_modulus > 0.0))
    throw std::invalid_argument("bilayer: both materials need a positive thickness and modulus");
  const double m = layer.thickness / base.thickness;
  const double n = layer.youngs_modulus / base.youngs_modulus;
  const double t = 6.0 * (1.0 + m) * (1.0 + m) /
                   (3.0 * (1.0 + m) * (1.0 + m) + (1.0 + m * n) * (m * m + 1.0 / (m * n)));
  return t / (base.thickness + layer.thickness);
}

int add_bilayer_hinges(Membrane& m, const Pattern& pattern, const Material& resin, int side,
                       const Pattern* all_coats) {
  const Model& model = m.sheet.model;
  const Points& x = m.state.x;
  const double per_strain = bilayer_curvature_per_strain(m.sheet.material, resin);
  const double d_latex = bending_stiffness(m.sheet.material);
  const double d = d_latex + bending_stiffness(resin);
  const double sign = side >= 0 ? 1.0 : -1.0;
  const auto& tris = m.sheet.triangles;
  const auto half = half_edges(tris);
  std::map<std::pair<int, int>, int> existing;
  Hinges& h = m.sheet.model.hinges;
  for (int e = 0; e < h.size(); ++e) existing[{h.v[e][0], h.v[e][1]}] = e;

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
    const double covered = it != existing.end() ? m.hinge_coverage[old] : 0.0;
    const Vec2 pc = x.col(c).head<2>(), pd = x.col(dd).head<2>();
    const double own = fraction_inside(pattern, pc, pd, 8);
    if (own <= 0.0) continue;
    const double f =
        std::min(own, (all_coats ? fraction_inside(*all_coats, pc, pd, 8) : 1.0) - covered);
    if (f <= 1e-12) continue;
    const Triangle& t1 = tris[left.tri];
    const Triangle& t2 = tris[right->second.tri];
    const Mat2 fg = 0.5 * (deformation(model, x, t1[0], t1[1], t1[2]) +
                           deformation(model, x, t2[0], t2[1], t2[2]));
    // A hinge partly inside the coat takes the share f of its spontaneous curvature, and its
    // moment is that curvature times the stiffness the bending elements there have: the coat
    // and the bare latex beside it in series, as membrane.cpp's impregnate combines them. With
    // the coat's full stiffness instead, a coat's edge would carry the moment of the coat
    // against the bending stiffness of the latex (a thousandth of it) and crease.
    const auto d_edge = [&](double share) { return 1.0 / ((1.0 - share) / d_latex + share / d); };
    const Eigen::Vector2d ev = (x.col(b) - x.col(a)).head<2>();
    if (!(ev.norm() > 0.0)) continue;
    const double full =
        sign * unit_moment(f * per_strain * misfit_strain(fg), ev) * d_edge(covered + f);
    if (it != existing.end()) {
      // The earlier coats' curvature at the stiffness of all the coats on this hinge.
      const double before = m.hinge_full_moment[old] / d_edge(covered);
      m.hinge_full_moment[old] = before * d_edge(covered + f) + full;
      m.hinge_coverage[old] += f;
    } else {
      h.add({a, b, c, dd}, 0.0);
      m.hinge_full_moment.push_back(full);
      m.hinge_coverage.push_back(f);
    }
    ++count;
  }
  update_hinge_moments(m);
  return count;
}

void update_hinge_moments(Membrane& m) {
  Hinges& h = m.sheet.model.hinges;
  const double share = m.releasing ? 1.0 - m.release_level : 0.0;
  for (int e = 0; e < h.size(); ++e)
    h.moment[e] = share * m.hinge_full_moment[static_cast<size_t>(e)];
}

}  // namespace membra
