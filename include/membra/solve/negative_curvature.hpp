#pragma once
// Where the energy curves down most at a saddle: the most negative curvature of the exact
// Hessian H in the metric D = diag|H|, by Lanczos on H shifted just positive definite
// (docs/solver.md, "The saddle's escape"). Newton's power iteration on its projected matrix
// cannot separate a small negative eigenvalue from the wrinkling latex's many soft positive
// modes; a shift that barely makes H positive definite turns that eigenvalue into the largest of
// the shifted inverse, so twenty solves find it.
#include <functional>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "membra/solve/hessian_assembler.hpp"

namespace membra {

struct CurvatureSearch {
  bool found = false;         // curvature below -1e-8: a negative curvature, not a zero mode's
  Eigen::VectorXd direction;  // unit length in the metric D
  double curvature = 0.0;     // direction.H.direction / direction.D.direction (D's units)
  double shift = 0.0;         // the shift s (units of D) at which H + s D factorized, or 0
  int factorizations = 0;     // attempts on the ladder of shifts
};

// A sparse Cholesky factorization the search works with (Newton's CHOLMOD factor): `factorize`
// takes a lower triangle and returns false where the matrix is not positive definite; `solve`
// applies the last factor's inverse.
struct CholeskyFactor {
  std::function<bool(const Eigen::SparseMatrix<double>&)> factorize;
  std::function<Eigen::VectorXd(const Eigen::VectorXd&)> solve;
};

// `h` holds H (without shifts) and is left so; `f` is left holding H + s D factored. The ladder
// of shifts starts at first_shift (or above where H's own diagonal says no smaller shift can
// work) and grows by sqrt 10 up to 1e6; `start` is Lanczos's first vector (the last direction
// found, or any nonzero one). Every entry of `metric` must be positive.
CurvatureSearch most_negative_curvature(HessianAssembler& h, const Eigen::VectorXd& metric,
                                        const Eigen::VectorXd& start, double first_shift,
                                        const CholeskyFactor& f);

}  // namespace membra
