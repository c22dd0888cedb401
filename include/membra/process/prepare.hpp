#pragma once
// Scene preparation: the membrane a scene describes, built and pinned, with the memory checked
// before anything is allocated and the force scale of the convergence test.
#include <chrono>
#include <optional>

#include "membra/model/continuum_sheet.hpp"
#include "membra/model/membrane.hpp"
#include "membra/process/scene.hpp"

namespace membra {

// The membrane a scene describes, ready to run.
struct PreparedScene {
  Membrane membrane;
  int pinned = 0;            // particles pinned by the scene's pins
  double force_scale = 0.0;  // k_stretch x grid spacing, N: the unit of the relative residual
  // When the run's wall-time budget (simulation.max_seconds) ends; none: no budget.
  std::optional<std::chrono::steady_clock::time_point> deadline;
};

// Builds the membrane of a scene without running it (what `membra validate` checks). Throws
// InputError naming the scene field when the scene cannot be built.
PreparedScene prepare_scene(const Scene& scene);

// The continuum sheet a scene describes, before meshing: the sheet, its mesh settings, and every
// impregnate step's outlines traced on its frame and pulled back to the natural sheet.
ContinuumSpec continuum_spec(const Scene& scene);

// Pins what `pins` select (in addition to the pins there are). Throws InputError at `where`
// when a pin selects no particle.
int pin(const std::vector<PinSpec>& pins, const std::string& where, PreparedScene& p);

}  // namespace membra
