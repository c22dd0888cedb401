#pragma once
// Stage 2's optimiser: bounded limited-memory BFGS (NLopt's LD_LBFGS, densities within [0, 1])
// on the density problem's objective and adjoint gradient. Every evaluation is a warm-started
// equilibrium; one that finds no stable equilibrium is reported to the optimiser as a much worse
// value, so its line search steps back.
#include <functional>
#include <string>
#include <vector>

#include "membra/design/density_problem.hpp"

namespace membra {

struct DensityOptimizerOptions {
  int evaluations = 60;           // objective evaluations (forward + adjoint solves) at most
  double max_seconds = 0.0;       // wall time at most (0: none)
  double relative_change = 1e-6;  // stop when the objective changes by less, relatively
};

struct DensityIterate {
  int index = 0;
  double objective = 0.0;
  double rms = 0.0;  // m: sqrt of the aligned distance
  double gradient_norm = 0.0;
  double seconds = 0.0;  // since the optimisation began
  long newton_iterations = 0;
  bool converged = false, restarted = false, best = false;
};

struct DensityOptimum {
  Eigen::VectorXd rho;  // the best densities found
  double objective = 0.0, rms = 0.0;
  std::vector<DensityIterate> history;
  std::string stopped;  // why the optimiser stopped
};

DensityOptimum optimize_density(DensityProblem& problem, const Eigen::VectorXd& start,
                                const DensityOptimizerOptions& options,
                                const std::function<void(const DensityIterate&)>& progress = {});

}  // namespace membra
