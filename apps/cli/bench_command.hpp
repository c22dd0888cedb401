#pragma once
// `membra bench`: the solvers side by side on P(n), as a table or JSON.
#include <string>
#include <vector>

#include "membra/process/bench.hpp"

namespace membra::cli {

struct BenchArgs {
  std::vector<int> sizes{32, 64};
  std::vector<std::string> solvers{kBenchSolvers.begin(), kBenchSolvers.end()};
  double budget = 60.0;
  bool json = false;
  std::string json_out;  // also write the JSON here, with the table on stdout
  bool quiet = false;
  // --scenes: also the forward examples at scene_sizes with the equilibrium solvers.
  bool scenes = false;
  std::vector<int> scene_sizes{64, 128};
  std::vector<std::string> scene_solvers{"static", "newton"};
  // simulation.multilevel for the scene runs: each value a run of its own (0: one grid).
  std::vector<int> scene_multilevel{0};
  std::vector<std::string> scene_files{
      "examples/exp3_parallel.json", "examples/synclastic_ellipse.json",
      "examples/anticlastic_hyperbola.json", "examples/exp5_shrink.json"};
  // The models the scenes run on: the lattice at scene_sizes, the continuum on its default mesh
  // scaled by each of scene_mesh_scales (max_edge times it, elements_across over it).
  std::vector<std::string> scene_models{"lattice", "continuum"};
  std::vector<double> scene_mesh_scales{1.0, 0.5};
};

int cmd_bench(const BenchArgs& args);

}  // namespace membra::cli
