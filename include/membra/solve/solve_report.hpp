#pragma once
// What every solver reports about a run.
#include <chrono>
#include <string>

#include "membra/geometry/vec.hpp"

namespace membra {

struct SolveReport {
  bool converged = false;          // residual_relative <= tolerance at the end
  bool diverged = false;           // stopped on NaN/Inf or blow-up; the state is not usable
  std::string message;             // why it stopped, and what to try if it failed
  double residual = 0.0;           // max |static force| over free particles at the end, N
  double residual_relative = 0.0;  // residual / force scale (k_stretch x grid spacing)
  long iterations = 0;             // time steps or solver iterations taken
  long force_passes = 0;           // full force evaluations
  double wall_seconds = 0.0;
};

// Diagonal of the bounding box of the positions, m: a sheet 100x its initial extent has blown up.
double sheet_extent(const Points& x);

// Wall time since construction, for the reports.
class Stopwatch {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// "NAME: converged after N iterations, residual R (tolerance T)".
std::string summary_message(const std::string& name, const SolveReport& r, double tolerance,
                            const char* unit = "iterations");

// Progress of a long run, passed to a callback every so often.
struct Progress {
  std::string stage;  // what is being solved ("release 3/10"), set by the caller of a solver
  long iteration = 0;
  long max_iterations = 0;
  double residual_relative = 0.0;
  double wall_seconds = 0.0;
};

}  // namespace membra
