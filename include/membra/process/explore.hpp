#pragma once
// Multistability: a pattern may have several stable forms, and which one a release ends in can
// hang on the sheet's imperfections. simulation.explore = N releases the scene N times — the
// first with its own imperfection, the others with seeded random mixes of low modes — and
// groups the stable end states into distinct forms (docs/process.md, "Several stable forms").
#include "membra/core/progress.hpp"
#include "membra/process/run_result.hpp"
#include "membra/process/scene.hpp"

namespace membra {

// Two end states are one form when their particles lie within this share of the sheet's size
// (the diagonal of its end state's bounding box) of each other, RMS, after the best rigid motion
// (no mirror) of a free sheet; a pinned one is compared where it is.
inline constexpr double kSameFormTolerance = 0.01;

// The scene for release k of an exploration: every path step's imperfection random
// (perturb_randomly) with its seed + k; k = 0 is the scene as it is.
Scene exploration_scene(const Scene& scene, int k);

// Releases `scene` k = 1 .. explore - 1 more times and fills first.branches, .explored and
// .unsettled; `first` is release 0's result.
void explore_branches(const Scene& scene, RunResult& first, const ProgressFn& progress = {});

}  // namespace membra
