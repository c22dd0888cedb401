#pragma once
// Static equilibrium by Newton's method on the exact, analytically assembled Hessian
// (hessian_assembler.hpp) with sparse Cholesky (CHOLMOD, symbolic analysis done once per solve):
//  - where the Hessian is positive definite, the plain Newton step (quadratic convergence);
//  - where it is indefinite (a compressed sheet before it buckles), the projected Hessian (each
//    element's Hessian made positive semi-definite) plus a shift in the stiffness-diagonal
//    metric whose size is remembered across iterations;
//  - at a saddle (small forces, indefinite Hessian), a step along the direction of most negative
//    curvature, found by power iteration with the factored projected matrix;
//  - an energy line search on every step.
// An end state counts as converged only when the forces are small and the exact Hessian is
// positive definite, so a saddle is never reported as an equilibrium. A sheet with no pins is
// held by a gauge that removes exactly its rigid motions (rigid_gauge.hpp). docs/solver.md.
#include <functional>
#include <memory>

#include "membra/model/model.hpp"
#include "membra/solve/hessian_assembler.hpp"
#include "membra/solve/solve_report.hpp"

namespace membra {

struct NewtonCache;  // newton_workspace.hpp

struct NewtonOptions {
  double tolerance = 1e-6;   // converged when max |static force| <= tolerance x force_scale
  double force_scale = 1.0;  // N
  long max_iterations = 500;
  double max_seconds = 0.0;  // wall-time budget (0: none)
  // Plane stress: every z coordinate held (for a sheet lying in the xy plane), so a compressed
  // region cannot buckle; the in-plane stress problems of the tests and the measures use it.
  bool in_plane = false;
  // Pseudo-transient continuation instead of line-searched Newton steps away from a minimum
  // (the solver "ptc"; measured against Newton in docs/performance.md).
  bool continuation = false;
  // On a continuum sheet, curve each Newton step by the tangent correction
  // (tangent_correction.hpp), which takes back the stretch a bending step brings.
  bool tangent_correction = true;
  std::function<void(const Progress&)> progress;
  // Keeps the sparsity pattern and symbolic analysis for the next solve of the same sheet (the
  // next increment of a path); none: every solve sets up its own.
  std::shared_ptr<NewtonCache> cache;
};

// Moves the free particles of `state` to a nearby stable equilibrium (velocities set to zero).
// Never throws on failure: the report says what happened.
SolveReport solve_newton(const Model& model, State& state, const NewtonOptions& options);

// An empty cache for NewtonOptions::cache (its type is complete only where CHOLMOD is seen).
std::shared_ptr<NewtonCache> make_newton_cache();

}  // namespace membra
