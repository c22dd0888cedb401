#pragma once
// Checks shared by the element and mechanics tests (they link membra).
#include <array>
#include <cmath>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <gtest/gtest.h>

#include "membra/model/model.hpp"
#include "membra/solve/hessian_assembler.hpp"

namespace membra {

// Element 0 of `s` on particles 0..N-1 at positions x: its forces match central differences of
// its energy, and its Hessian central differences of its forces (relative 1e-6), and the
// projected Hessian is positive semi-definite.
template <class Set>
void expect_kernel_matches_finite_differences(const Set& s, const Points& x, const char* what) {
  constexpr int n = 3 * Set::kArity;
  const int cols = static_cast<int>(x.cols());
  Points f = Points::Zero(3, cols);
  s.add_forces(x, nullptr, 0, 1, f);
  const Eigen::Matrix<double, n, n> hess = s.hessian(0, x, false);
  const double step = 1e-7;
  for (int c = 0; c < n; ++c) {
    Points xp = x, xm = x;
    xp(c % 3, c / 3) += step;
    xm(c % 3, c / 3) -= step;
    EXPECT_NEAR(-f(c % 3, c / 3), (s.energy(0, xp) - s.energy(0, xm)) / (2.0 * step),
                1e-6 * f.norm())
        << what << " " << c;
    Points fp = Points::Zero(3, cols), fm = Points::Zero(3, cols);
    s.add_forces(xp, nullptr, 0, 1, fp);
    s.add_forces(xm, nullptr, 0, 1, fm);
    const Eigen::Matrix<double, n, 1> col = -(fp - fm).reshaped() / (2.0 * step);
    EXPECT_LT((hess.col(c) - col).norm(), 1e-6 * hess.norm()) << what << " " << c;
  }
  using Eigensolver = Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, n, n>>;
  EXPECT_GE(Eigensolver(s.hessian(0, x, true)).eigenvalues().minCoeff(), -1e-9 * hess.norm())
      << what;
}

// A flat patch of equilateral triangles for the bending tests: its positions, counter-clockwise
// triangles and the particles on its rim.
struct TriPatch {
  Points x;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> rim;
};

// An (n + 1)^2 patch of equilateral triangles of side h, turned by `angle`, with its rim.
inline TriPatch tri_patch(int n, double h, double angle) {
  TriPatch m;
  m.x = Points::Zero(3, (n + 1) * (n + 1));
  const double c = std::cos(angle), s = std::sin(angle);
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double u = (i + 0.5 * j) * h, w = j * h * std::sqrt(3.0) / 2.0;
      m.x.col(id(i, j)) = Vec3(c * u - s * w, s * u + c * w, 0.0);
      if (i == 0 || j == 0 || i == n || j == n) m.rim.push_back(id(i, j));
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
      m.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

// The smallest eigenvalue of the energy's Hessian in the out-of-plane (z) coordinates of the
// free particles: negative once a flat sheet has buckled.
inline double smallest_out_of_plane_eigenvalue(const Model& m, const Points& x) {
  const Eigen::MatrixXd h = Eigen::MatrixXd(potential_hessian(m, x));
  std::vector<int> z;
  for (int p = 0; p < m.num_particles(); ++p)
    if (!m.pinned(p)) z.push_back(3 * p + 2);
  Eigen::MatrixXd hz(z.size(), z.size());
  for (size_t a = 0; a < z.size(); ++a)
    for (size_t b = 0; b < z.size(); ++b) hz(a, b) = h(z[a], z[b]);
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(hz).eigenvalues()(0);
}

}  // namespace membra
