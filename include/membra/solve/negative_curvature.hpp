#pragma once
// Where the energy curves down most at a saddle: the most negative curvature of the exact
// Hessian H in the metric D = diag|H|, by inverse iteration on H shifted just positive definite
// (docs/solver.md, "The saddle's escape"). Newton's power iteration on its projected matrix
// cannot separate a small negative eigenvalue from the wrinkling latex's many soft positive
// modes; a shift that barely makes H positive definite puts that eigenvalue nearest zero, so a
// few solves find it.
#include <functional>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "membra/solve/hessian_assembler.hpp"

namespace membra {

struct CurvatureSearch {
  bool found = false;         // direction has negative curvature: direction.H.direction < 0
  Eigen::VectorXd direction;  // unit length in the metric D
  double curvature = 0.0;     // direction.H.direction / direction.D.direction (D's units)
  double shift = 0.0;         // the shift s (units of D) at which H + s D factorized, or 0
  int factorizations = 0;     // attempts on the ladder of shifts
};

// A sparse Cholesky factorization the search works with (Newton's CHOLMOD factor): `factorize`
// takes a lower triangle and returns false where the matrix is not positive definite; `solve`
// applies the last factor's inverse.
struct Factorization {
  std::function<bool(const Eigen::SparseMatrix<double>&)> factorize;
  std::function<Eigen::VectorXd(const Eigen::VectorXd&)> solve;
};

// `h` holds H (without shifts) and is left so; `f` is left holding H + s D factored. The ladder
// of shifts starts at first_shift (or where H's own diagonal says no smaller shift can work) and
// grows by sqrt 10 up to 1e6; `start` is the inverse iteration's first vector (the last
// direction found, or any).
CurvatureSearch most_negative_curvature(HessianAssembler& h, const Eigen::VectorXd& metric,
                                        const Eigen::VectorXd& start, double first_shift,
                                        const Factorization& f);

}  // namespace membra
