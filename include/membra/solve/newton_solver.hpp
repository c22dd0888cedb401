#pragma once
// Static equilibrium by Newton's method with a Levenberg-Marquardt shift: the exact Hessian
// (springs analytic, bending by differences of the analytic gradient) plus mu I, with mu grown
// until a sparse Cholesky factorization (CHOLMOD) succeeds, i.e. the system is positive
// definite, and shrunk after each accepted step; a backtracking line search on the energy keeps
// every step downhill. A sheet with no pins has six coordinates held to remove its rigid
// motions. Experimental: fast on exp2, stalls on exp3 (docs/process.md).
#include <functional>

#include <Eigen/SparseCore>

#include "membra/model/model.hpp"
#include "membra/solve/solve_report.hpp"

namespace membra {

struct NewtonOptions {
  double tolerance = 1e-6;   // converged when max |static force| <= tolerance x force_scale
  double force_scale = 1.0;  // N
  long max_iterations = 500;
  double max_seconds = 0.0;  // wall-time budget (0: none)
  std::function<void(const Progress&)> progress;
};

// Hessian of the potential energy at x over all 3N coordinates (pins ignored), N/m.
Eigen::SparseMatrix<double> potential_hessian(const Model& model, const Points& x);

// Moves the free particles of `state` to a nearby stable equilibrium (velocities set to zero).
// Never throws on failure: the report says what happened.
SolveReport solve_newton(const Model& model, State& state, const NewtonOptions& options);

}  // namespace membra
