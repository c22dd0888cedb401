// The saddle's escape direction (solve/negative_curvature.hpp): on a continuum sheet squeezed
// flat, the shifted Lanczos search must find the exact Hessian's most negative curvature in
// the metric D = diag|H|, as a dense eigen-decomposition gives it, and a shift that brackets it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include "membra/model/continuum_sheet.hpp"
#include "membra/solve/hessian_assembler.hpp"
#include "membra/solve/negative_curvature.hpp"

namespace negative_curvature_test {

using namespace membra;

// A 40 x 30 mm continuum sheet at 6 mm (not square, so its modes are not paired), flat, scaled
// in-plane by `squeeze` about its corner; the outline's particles held.
struct Squeezed {
  explicit Squeezed(double squeeze)
      : sheet(build_continuum_sheet([] {
          ContinuumSpec s;
          s.width = 0.04;
          s.height = 0.03;
          s.mesh.max_edge = 0.006;
          return s;
        }())) {
    x = sheet.model.reference;
    x.topRows(2) *= squeeze;
    for (Eigen::Index p = 0; p < x.cols(); ++p) {
      const Eigen::Vector3d r = sheet.model.reference.col(p);
      const bool rim = r.x() < 1e-9 || r.y() < 1e-9 || r.x() > 0.04 - 1e-9 || r.y() > 0.03 - 1e-9;
      for (int c = 0; c < 3; ++c) dof.push_back(rim ? -1 : ndof++);
    }
  }
  Sheet sheet;
  Points x;
  std::vector<int> dof;
  int ndof = 0;
};

// The smallest eigenvalue of H v = lambda D v, D the diagonal metric, densely.
double smallest_eigenvalue(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& d) {
  const Eigen::MatrixXd h = Eigen::MatrixXd(lower).selfadjointView<Eigen::Lower>();
  const Eigen::VectorXd s = d.cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd scaled = s.asDiagonal() * h * s.asDiagonal();
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(scaled, Eigen::EigenvaluesOnly)
      .eigenvalues()[0];
}

// Eigen's own sparse Cholesky in place of Newton's CHOLMOD factor (kept alive by the closures).
CholeskyFactor simplicial() {
  auto llt = std::make_shared<Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>>();
  return {[llt](const Eigen::SparseMatrix<double>& a) {
            llt->compute(a);
            return llt->info() == Eigen::Success;
          },
          [llt](const Eigen::VectorXd& b) { return Eigen::VectorXd(llt->solve(b)); }};
}

TEST(NegativeCurvature, FindsTheMostNegativeCurvatureOfASqueezedSheet) {
  Squeezed s(0.95);
  HessianAssembler h(s.sheet.model, s.dof, s.ndof);
  h.assemble(s.x, false);
  const Eigen::VectorXd before = h.diagonal();
  const Eigen::VectorXd metric = before.cwiseAbs().array() + 1e-12;  // positive, as Newton's
  const double lambda = smallest_eigenvalue(h.lower(), metric);
  ASSERT_LT(lambda, 0.0);  // squeezed flat: a saddle
  const CurvatureSearch c =
      most_negative_curvature(h, metric, Eigen::VectorXd::Ones(s.ndof), 1e-9, simplicial());
  std::printf("lambda %.6g, found %.6g at shift %.3g after %d factorizations\n", lambda,
              c.curvature, c.shift, c.factorizations);
  ASSERT_TRUE(c.found);
  EXPECT_NEAR(c.curvature / lambda, 1.0, 1e-4);  // inverse iteration: 0.076 off
  EXPECT_NEAR(c.direction.dot(metric.cwiseProduct(c.direction)), 1.0, 1e-12);
  EXPECT_GE(c.shift, -lambda);  // H + s D factorized: s above -lambda
  ASSERT_GT(c.factorizations, 1);
  EXPECT_LT(c.shift / std::sqrt(10.0), -lambda);  // the one below failed
  EXPECT_TRUE(h.diagonal() == before);            // the matrix comes back without its shift
}

TEST(NegativeCurvature, FindsNoneOnAStretchedSheet) {
  Squeezed s(1.1);
  HessianAssembler h(s.sheet.model, s.dof, s.ndof);
  h.assemble(s.x, false);
  const Eigen::VectorXd metric = h.diagonal().cwiseAbs().array() + 1e-12;
  ASSERT_GT(smallest_eigenvalue(h.lower(), metric), 0.0);
  const CurvatureSearch c =
      most_negative_curvature(h, metric, Eigen::VectorXd::Ones(s.ndof), 1e-9, simplicial());
  EXPECT_FALSE(c.found);
  EXPECT_EQ(c.factorizations, 1);  // positive definite at the first shift
}

}  // namespace negative_curvature_test
