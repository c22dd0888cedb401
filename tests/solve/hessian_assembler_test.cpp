// The Hessian assembler (solve/hessian_assembler.hpp): each element's block added into the fixed
// pattern through its lower triangle only, shifts taken off bit for bit.
#include <gtest/gtest.h>

#include <random>
#include <type_traits>
#include <vector>

#include "membra/model/continuum_sheet.hpp"
#include "membra/solve/hessian_assembler.hpp"

namespace hessian_assembler_test {

using namespace membra;

// A 40 mm continuum sheet at 8 mm (rim stencils repeat their corners: a particle twice in a
// block), bent into a saddle, its left edge's particles held in x and z (dof -1).
struct Bent {
  Bent()
      : sheet(build_continuum_sheet([] {
          ContinuumSpec s;
          s.width = s.height = 0.04;
          s.mesh.max_edge = 0.008;
          return s;
        }())) {
    x = sheet.model.reference;
    for (Eigen::Index p = 0; p < x.cols(); ++p)
      x(2, p) = 3.0 * x(0, p) * x(0, p) - 2.0 * x(1, p) * x(1, p) + 0.5 * x(0, p) * x(1, p);
    for (Eigen::Index p = 0; p < x.cols(); ++p)
      for (int c = 0; c < 3; ++c) dof.push_back(x(0, p) < 1e-9 && c != 1 ? -1 : ndof++);
  }
  Sheet sheet;
  Points x;
  std::vector<int> dof;
  int ndof = 0;
};

// Every element block scattered entry by entry into a dense matrix: what the assembler's sparse
// lower triangle must hold.
Eigen::MatrixXd dense_scatter(const Bent& b, bool project) {
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(b.ndof, b.ndof);
  b.sheet.model.for_each_set([&](const auto& set) {
    constexpr int n = 3 * std::decay_t<decltype(set)>::kArity;
    for (int e = 0; e < set.size(); ++e) {
      if (!set.active(e)) continue;
      const auto ids = set.ids(e);
      const auto block = set.hessian(e, b.x, project);
      for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
          const int dr = b.dof[static_cast<size_t>(3 * ids[static_cast<size_t>(r / 3)] + r % 3)];
          const int dc = b.dof[static_cast<size_t>(3 * ids[static_cast<size_t>(c / 3)] + c % 3)];
          if (dr >= 0 && dc >= 0) h(dr, dc) += block(r, c);
        }
    }
  });
  return h;
}

TEST(HessianAssembler, HoldsEveryElementsBlockWithHeldCoordinatesLeftOut) {
  const Bent b;
  ASSERT_LT(b.ndof, 3 * b.x.cols());  // some held
  for (const bool project : {false, true}) {
    HessianAssembler a(b.sheet.model, b.dof, b.ndof);
    const Eigen::SparseMatrix<double> full =
        a.assemble(b.x, project).selfadjointView<Eigen::Lower>();
    const Eigen::MatrixXd assembled(full);
    const Eigen::MatrixXd expected = dense_scatter(b, project);
    EXPECT_LE((assembled - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff())
        << project;
  }
}

TEST(HessianAssembler, TakesItsShiftsOffBitForBit) {
  const Bent b;
  HessianAssembler a(b.sheet.model, b.dof, b.ndof);
  const Eigen::SparseMatrix<double> assembled = a.assemble(b.x, false);
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Eigen::VectorXd shift(b.ndof);
  for (Eigen::Index k = 0; k < shift.size(); ++k) shift[k] = u(rng);
  a.add_to_diagonal(shift);
  a.add_to_diagonal(3.0 * shift);
  EXPECT_NE(a.diagonal(), Eigen::VectorXd(assembled.diagonal()));
  const Eigen::SparseMatrix<double>& back = a.remove_shifts();
  ASSERT_EQ(back.nonZeros(), assembled.nonZeros());
  for (Eigen::Index k = 0; k < back.nonZeros(); ++k)
    EXPECT_EQ(back.valuePtr()[k], assembled.valuePtr()[k]) << k;
}

}  // namespace hessian_assembler_test
