#pragma once
// Progress of a long run, passed to a callback every so often.
#include <functional>
#include <string>

namespace membra {

struct Progress {
  std::string stage;  // what is being solved ("release 3/10"), set by the caller of a solver
  long iteration = 0;
  long max_iterations = 0;
  double residual_relative = 0.0;
  double wall_seconds = 0.0;
  // How much of the current step's path was done before this solve (0..1; -1: not a path), and
  // of the whole run, its steps weighted by their increments (0..1; -1: unknown). Both count
  // finished increments only, so they grow in jumps and never go back.
  double step_done = -1.0;
  double run_done = -1.0;
};

// Called every so often by long runs; may be empty.
using ProgressFn = std::function<void(const Progress&)>;

}  // namespace membra
