#include "membra/solve/negative_curvature.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>

namespace membra {
namespace {

// The smallest shift s on a ladder (x sqrt 10 from `first`) for which H + s D factorizes into f,
// or 0. The most negative eigenvalue is at most every H_ii / D_ii (a Rayleigh quotient), so where
// H has negative diagonal entries (a compressed membrane's out-of-plane ones) no shift up to the
// largest -H_ii / D_ii can work: the ladder starts half as high again at the earliest. h is left
// without its shift.
double factor_shifted(HessianAssembler& h, const Eigen::VectorXd& metric, double first,
                      const CholeskyFactor& f, int& factorizations) {
  const double needed = (-h.diagonal().array() / metric.array()).maxCoeff();
  double applied = 0.0;
  bool factored = false;
  for (double shift = std::max({first, 1.5 * needed, 1e-12}); shift <= 1e6 && !factored;
       shift *= std::sqrt(10.0)) {
    h.add_to_diagonal((shift - applied) * metric);
    applied = shift;
    ++factorizations;
    factored = f.factorize(h.lower());
  }
  h.remove_shifts();
  return factored ? applied : 0.0;
}

}  // namespace

// With H + s D positive definite, the operator (H + s D)^-1 D is self-adjoint in D's inner
// product with eigenvalues 1 / (lambda + s): the most negative lambda gives the largest. Lanczos
// (with full re-orthogonalisation, 20 solves) finds it where several negative modes lie close
// together, as on a squeezed sheet, where as many steps of inverse iteration do not separate
// them (docs/solver.md, "The saddle's escape").
CurvatureSearch most_negative_curvature(HessianAssembler& h, const Eigen::VectorXd& metric,
                                        const Eigen::VectorXd& start, double first_shift,
                                        const CholeskyFactor& f) {
  CurvatureSearch s;
  s.shift = factor_shifted(h, metric, first_shift, f, s.factorizations);
  if (s.shift == 0.0) return s;
  const auto d_dot = [&](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    return a.dot(metric.cwiseProduct(b));
  };
  constexpr int kSteps = 20;
  std::vector<Eigen::VectorXd> q{start / std::sqrt(d_dot(start, start))};
  Eigen::VectorXd alpha(kSteps), beta(kSteps);
  int m = 0;
  for (; m < kSteps; ++m) {
    Eigen::VectorXd w = f.solve(metric.cwiseProduct(q[static_cast<size_t>(m)]));
    alpha[m] = d_dot(w, q[static_cast<size_t>(m)]);
    if (m + 1 == kSteps) {  // the last: no further vector
      ++m;
      break;
    }
    for (int pass = 0; pass < 2; ++pass)  // twice is enough (Kahan, Parlett)
      for (const Eigen::VectorXd& qi : q) w -= d_dot(w, qi) * qi;
    beta[m] = std::sqrt(d_dot(w, w));
    if (!(beta[m] > 1e-12 * alpha.head(m + 1).cwiseAbs().maxCoeff())) {  // invariant: exact
      ++m;
      break;
    }
    q.push_back(w / beta[m]);
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> t;
  t.computeFromTridiagonal(alpha.head(m), beta.head(std::max(m - 1, 0)),
                           Eigen::ComputeEigenvectors);
  if (t.info() != Eigen::Success) return s;
  const Eigen::VectorXd y = t.eigenvectors().col(m - 1);  // the largest Ritz value's (ascending)
  Eigen::VectorXd v = Eigen::VectorXd::Zero(start.size());
  for (int i = 0; i < m; ++i) v += y[i] * q[static_cast<size_t>(i)];
  v /= std::sqrt(d_dot(v, v));
  s.curvature = v.dot(h.multiply(v));
  s.found = s.curvature < -1e-8 && v.allFinite();
  s.direction = std::move(v);
  return s;
}

}  // namespace membra
