#pragma once
// Strain, force and stress of every spring, and a per-vertex stress for pictures from every
// element set's stress read-out.
#include <vector>

#include "membra/model/model.hpp"

namespace membra {

struct SpringStress {
  std::vector<double> strain;  // (l - l0) / l0
  std::vector<double> force;   // k (l - l0), N; > 0 tension
  std::vector<double> stress;  // force / (tributary width x thickness), Pa; 0 if width unknown
  double min_stress = 0.0, max_stress = 0.0;  // Pa, over springs with a known width
  double min_strain = 0.0, max_strain = 0.0;  // over all springs
  double min_force = 0.0, max_force = 0.0;    // N, over all springs
};

// Per-spring measures at positions x for a sheet of the given thickness (m).
SpringStress spring_stress(const Model& model, const Points& x, double thickness);

// Mean stress of the elements meeting at each particle that carry one (Pa), for colouring: every
// element set's read-out (model/elements/) at positions x for a sheet of that thickness (m).
std::vector<double> vertex_stress(const Model& model, const Points& x, double thickness);

}  // namespace membra
