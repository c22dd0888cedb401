#include "membra/design/conformal_flattening.hpp"

#include <stdexcept>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace membra {
namespace {

// The two vertices farthest apart along the footprint's larger extent.
std::pair<int, int> pins(const Points& x) {
  Eigen::Index lo = 0, hi = 0;
  const Vec3 extent = x.rowwise().maxCoeff() - x.rowwise().minCoeff();
  const int axis = extent.x() >= extent.y() ? 0 : 1;
  x.row(axis).minCoeff(&lo);
  x.row(axis).maxCoeff(&hi);
  return {static_cast<int>(lo), static_cast<int>(hi)};
}

// The unknowns: u_k, v_k of every vertex but the two pinned ones (their columns; -1 when pinned),
// and the pinned vertices' values.
struct Unknowns {
  std::vector<int> col;
  Eigen::VectorXd pinned;
  int free = 0;
};
Unknowns unknowns(const Points& x) {
  const int n = static_cast<int>(x.cols());
  const auto [a, b] = pins(x);
  Unknowns u;
  u.col.resize(2 * static_cast<size_t>(n));
  for (int k = 0; k < n; ++k)
    for (int c = 0; c < 2; ++c) u.col[2 * k + c] = (k == a || k == b) ? -1 : u.free++;
  u.pinned = Eigen::VectorXd::Zero(2 * n);
  for (int k : {a, b}) u.pinned.segment<2>(2 * k) = x.col(k).head<2>();
  return u;
}

}  // namespace

// Per triangle, in an orthonormal frame of its own plane (corners q0, q1, q2), the residual of
// the Cauchy-Riemann equations is sum_j W_j (u_j + i v_j) / sqrt(area), W_j = q_{j+2} - q_{j+1}
// as complex numbers (Levy et al. 2002); its real and imaginary parts are two rows of a linear
// least-squares problem in the free coordinates, solved by its normal equations.
Eigen::Matrix2Xd conformal_flattening(const Points& x, const std::vector<Triangle>& triangles) {
  if (triangles.empty()) throw std::invalid_argument("the mesh has no faces to flatten");
  const int n = static_cast<int>(x.cols());
  const auto [col, pinned, free] = unknowns(x);
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<double> rhs;
  int row = 0;
  for (const Triangle& t : triangles) {
    const Vec3 p0 = x.col(t[0]), e1 = x.col(t[1]) - p0, e2 = x.col(t[2]) - p0;
    const double area = 0.5 * e1.cross(e2).norm();
    if (!(area > 0.0)) continue;
    const Vec3 ex = e1.normalized(), ey = e1.cross(e2).cross(e1).normalized();
    const Vec2 q[3] = {Vec2::Zero(), Vec2(e1.norm(), 0.0), Vec2(e2.dot(ex), e2.dot(ey))};
    const double s = 1.0 / std::sqrt(area);
    double r_re = 0.0, r_im = 0.0;  // the pinned coordinates' share, moved to the right
    for (int j = 0; j < 3; ++j) {
      const Vec2 w = s * (q[(j + 2) % 3] - q[(j + 1) % 3]);
      const int k = t[j];
      // Re: w.x u - w.y v;  Im: w.y u + w.x v.
      const double coef[2][2] = {{w.x(), -w.y()}, {w.y(), w.x()}};
      for (int part = 0; part < 2; ++part)
        for (int c = 0; c < 2; ++c) {
          const int cc = col[2 * k + c];
          if (cc >= 0)
            entries.emplace_back(row + part, cc, coef[part][c]);
          else
            (part == 0 ? r_re : r_im) -= coef[part][c] * pinned[2 * k + c];
        }
    }
    rhs.push_back(r_re);
    rhs.push_back(r_im);
    row += 2;
  }
  Eigen::SparseMatrix<double> m(row, free);
  m.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(
      Eigen::SparseMatrix<double>(m.transpose() * m));
  if (solver.info() != Eigen::Success)
    throw std::invalid_argument("the mesh cannot be flattened (disconnected or degenerate)");
  const Eigen::VectorXd sol =
      solver.solve(m.transpose() * Eigen::Map<const Eigen::VectorXd>(rhs.data(), row));
  Eigen::Matrix2Xd uv(2, n);
  for (int k = 0; k < n; ++k)
    for (int c = 0; c < 2; ++c) {
      const int cc = col[2 * k + c];
      uv(c, k) = cc >= 0 ? sol[cc] : pinned[2 * k + c];
    }
  return uv;
}

}  // namespace membra
