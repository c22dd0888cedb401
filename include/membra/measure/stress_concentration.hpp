#pragma once
// How much a cut or a hole concentrates stress: the peak stress next to it against the stress
// far from it (the paper's experiment 7; Kirsch's factor 3 for a round hole under tension).
#include <string>
#include <vector>

#include "membra/core/vec.hpp"
#include "membra/model/model.hpp"

namespace membra {

// Where a cut or hole was, in paper coordinates (m): the midpoints of the springs a cut removed
// (on the continuum: of the mesh edges it opened), or the positions of the particles a hole
// removed.
struct StressFeature {
  std::string name;  // the scene step, e.g. "/protocol/2"
  std::string kind;  // "cut" or "hole"
  std::vector<Vec2> where;
};

struct StressConcentration {
  std::string name, kind;
  double peak_stress = 0.0;       // Pa: largest principal stress within `near` of the feature
  Vec2 peak_at = Vec2::Zero();    // paper position of that particle, m
  double far_field_stress = 0.0;  // Pa: median largest principal stress beyond `far`
  double concentration = 0.0;     // peak / far field (0 when the far field carries no tension)
  // Holes: the edge value extrapolated from off the staircase edge (hole_edge.hpp).
  bool has_edge = false;
  double edge_stress = 0.0;         // Pa, largest over the rays
  double edge_concentration = 0.0;  // edge_stress / far field
  double edge_angle = 0.0;          // rad from +x (paper), the ray of edge_stress
  double hole_radius = 0.0;         // m, the circle with the hole's area
};

// Distances are measured between paper positions (model.reference), so they mean the same
// before and after the release. `stress` is per particle (e.g. max_principal_stress).
StressConcentration stress_concentration(const Model& model, const std::vector<double>& stress,
                                         const StressFeature& feature, double near, double far);

}  // namespace membra
