#pragma once
// How the viewer shows the session: colour map and range, 2-D or 3-D, camera, what is drawn,
// the brush. Kept apart from the window so scripts and tests can set it without one.
#include <array>
#include <optional>
#include <utility>

#include "membra/geometry/orbit_camera.hpp"
#include "membra/view/color_field.hpp"

namespace membra {

struct ViewSettings {
  ColorMode color = ColorMode::stress;
  std::optional<std::pair<double, double>> range;  // manual colour range, display units
  bool flat = false;                               // the 2-D view instead of the 3-D one
  OrbitCamera camera;
  bool camera_fitted = false;  // false: fit the camera to the sheet before the next frame
  bool show_surface = true;
  std::array<bool, 4> show_springs{false, false, false, false};  // stretch, shear, flex, added
  bool show_particles = false;
  double brush_radius = 0.008;       // m
  long iterations_per_frame = 400;   // solver iterations per frame at most (script mode: exactly)
  double seconds_per_frame = 0.015;  // wall-time budget of the simulation in one frame
  bool playing = true;               // the live simulation runs
};

}  // namespace membra
