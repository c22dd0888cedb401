#pragma once
// Running a scene: prepare its membrane, carry out the protocol step by step (each step's path
// followed to equilibrium), summarise the end state.
#include "membra/core/progress.hpp"
#include "membra/process/prepare.hpp"
#include "membra/process/run_result.hpp"
#include "membra/process/scene.hpp"

namespace membra {

// Runs a scene to the end. `progress` (optional) is called every so often. Throws InputError
// when a step cannot be carried out (a pattern that covers no spring).
RunResult run_scene(const Scene& scene, const ProgressFn& progress = {});

}  // namespace membra
