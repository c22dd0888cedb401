#pragma once
// Static equilibrium by projected Newton: each element's Hessian is made positive semi-definite
// (compressed springs lose their negative geometric stiffness, bending blocks their negative
// eigenvalues), the sparse system is solved by Cholesky (LDL^T), and a backtracking line search
// on the energy keeps every step downhill. Converges in tens of iterations where first-order
// methods need hundreds of thousands: the resin is ~1000x stiffer than the latex, and bending
// is ~1e4x softer than stretching.
#include <functional>

#include <Eigen/SparseCore>

#include "membra/model/model.hpp"
#include "membra/solve/solve_report.hpp"

namespace membra {

struct NewtonOptions {
  double tolerance = 1e-6;   // converged when max |static force| <= tolerance x force_scale
  double force_scale = 1.0;  // N
  long max_iterations = 500;
  std::function<void(const Progress&)> progress;
};

// Hessian of the potential energy at x over all 3N coordinates (pins ignored), N/m.
Eigen::SparseMatrix<double> potential_hessian(const Model& model, const Points& x);

// Moves the free particles of `state` to a nearby stable equilibrium (velocities set to zero).
// Never throws on failure: the report says what happened.
SolveReport solve_newton(const Model& model, State& state, const NewtonOptions& options);

}  // namespace membra
