#pragma once
// A bundled example run in full on an n x n sheet, optionally with another solver or tolerance:
// the form-comparing tests' common start (solver agreement, mesh convergence).
#include <string>
#include <vector>

#include "membra/io/scene.hpp"
#include "membra/process/run.hpp"

namespace membra {

inline RunResult run_example(const std::string& name, int n, const std::string& solver = "",
                             const std::string& tolerance = "") {
  const std::string res = std::to_string(n);
  std::vector<std::string> set = {"sheet.resolution=[" + res + "," + res + "]"};
  if (!solver.empty()) set.push_back("simulation.solver=" + solver);
  if (!tolerance.empty()) set.push_back("simulation.tolerance=" + tolerance);
  return run_scene(load_scene(std::string(MEMBRA_SOURCE_DIR) + "/examples/" + name, set));
}

}  // namespace membra
