#pragma once
// What every solver reports about a run.
#include <string>

#include "membra/core/progress.hpp"
#include "membra/core/stopwatch.hpp"
#include "membra/core/vec.hpp"

namespace membra {

struct SolveReport {
  bool converged = false;             // residual_relative <= tolerance at the end
  bool diverged = false;              // stopped on NaN/Inf or blow-up; the state is not usable
  std::string message;                // why it stopped, and what to try if it failed
  double residual = 0.0;              // max |static force| over free particles at the end, N
  double residual_relative = 0.0;     // residual / force scale (k_stretch x grid spacing)
  long iterations = 0;                // time steps or solver iterations taken
  long force_passes = 0;              // full force evaluations
  long factorizations = 0;            // newton: sparse Cholesky factorizations
  long setups = 0;                    // newton: patterns and symbolic analyses set up
  long negative_curvature_steps = 0;  // newton: steps taken along negative curvature (saddles)
  long lanczos_steps = 0;             // newton: of those, found by the shifted Lanczos search
  long tangent_corrections = 0;       // newton: steps curved by the tangent correction
  long increments = 0;                // path increments solved (a retried one counts once)
  long increments_halved = 0;         // newton: increments that failed and were taken in halves
  bool saddle = false;       // newton: stopped at a point where the energy is not a minimum
  bool out_of_time = false;  // stopped unconverged because the run's wall-time budget ran out
  double wall_seconds = 0.0;
};

// Diagonal of the bounding box of the positions, m: a sheet 100x its initial extent has blown up.
double sheet_extent(const Points& x);

// "NAME: converged after N iterations, residual R (tolerance T)".
std::string summary_message(const std::string& name, const SolveReport& r, double tolerance,
                            const char* unit = "iterations");

}  // namespace membra
