#pragma once
// `membra sweep SWEEP.json [--scheduler ADDR] --out DIR`: a sweep on a Dask cluster. Sweeps live
// in the Python module (docs/sweeps.md); this command hands its arguments to it.
#include <string>

namespace membra::cli {

struct SweepArgs {
  std::string file;
  std::string out_dir;    // default out/<sweep name>
  std::string scheduler;  // default: a local cluster
  int workers = 2;
  bool no_resume = false;
  bool quiet = false;
};

// Replaces this process by `python3 -m membra sweep ...`; returns only when that cannot start
// (exit code 1, with a message).
int cmd_sweep(const SweepArgs& args);

}  // namespace membra::cli
