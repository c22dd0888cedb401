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
};

// Called every so often by long runs; may be empty.
using ProgressFn = std::function<void(const Progress&)>;

}  // namespace membra
