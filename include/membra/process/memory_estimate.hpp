#pragma once
// How much memory a scene will need, so a grid the machine cannot hold is refused before
// anything is allocated (rather than failing, or swapping, half-way through a run).
#include "membra/process/scene.hpp"

namespace membra {

// Bytes a run of the scene needs at most, from its particle count and solver: about 2.5 kB per
// particle for the model, state, measures and the static or time-stepping solvers, 16 kB with
// the Newton solver's sparse Cholesky factor (measured: 1.7 and 12 kB; docs/errors.md).
double estimate_memory(const Scene& scene);

// The machine's physical memory in bytes (MemTotal), or 0 if unknown.
double machine_memory();

// Throws InputError at /sheet/resolution, with the estimate and `available`, when the scene
// needs more than `available` bytes (no check when available <= 0).
void check_memory(const Scene& scene, double available);

}  // namespace membra
