#pragma once
// Running a scene: build the sheet, apply pins and loads, solve, summarise.
#include <functional>

#include "membra/io/scene.hpp"
#include "membra/measure/shape.hpp"
#include "membra/solve/solve_report.hpp"

namespace membra {

// The model a scene describes, ready to solve, and its initial state.
struct PreparedScene {
  Sheet sheet;
  State state;
  int pinned = 0;            // pinned particles
  double force_scale = 0.0;  // k_stretch x grid spacing, N: the unit of the relative residual
};

struct RunResult {
  PreparedScene prepared;  // the sheet; prepared.state holds the final state
  SolveReport solve;
  double elastic_energy = 0.0;  // J, springs
  double bending_energy = 0.0;  // J
  double gravity_energy = 0.0;  // J
  double kinetic_energy = 0.0;  // J
  ShapeSummary shape;
};

// Builds the model of a scene without running it (this is what `membra validate` checks).
// Throws InputError naming the scene field when the scene cannot be built.
PreparedScene prepare_scene(const Scene& scene);

// Runs a scene to the end. `progress` (optional) is called every so often.
RunResult run_scene(const Scene& scene, const std::function<void(const Progress&)>& progress = {});

}  // namespace membra
