#pragma once
// The continuum model's mesh-convergence check (docs/performance.md, "Scenes on both models"): a
// form on a scene's mesh against the same scene at half the element size (max_edge halved,
// elements_across doubled) must keep the global form's classification, and its global total K
// within 5 %, global height within 3 % and energy within 2 %.
#include <string>
#include <vector>

namespace membra {

// What the check reads of a form (report.json's curvature.global, shape.global_height, energy).
struct FormReading {
  std::string classification;    // the global form's
  double total_curvature = 0.0;  // rad, global total K
  double height = 0.0;           // m, global height
  double energy = 0.0;           // J
};

struct MeshConvergence {
  bool same_classification = false;
  // |fine - coarse| / |fine| of each (infinite where fine is 0 and coarse is not).
  double curvature_change = 0.0, height_change = 0.0, energy_change = 0.0;
  bool passes() const;
  // "K 2.5 %, height 2.7 %, energy 140 %: fails (energy)": the changes and the verdict.
  std::string line() const;
};

MeshConvergence compare_meshes(const FormReading& coarse, const FormReading& fine);

// The exponent p of wall ~ vertices^p fitted by least squares on log-log (0 with fewer than two
// distinct vertex counts).
double cost_exponent(const std::vector<int>& vertices, const std::vector<double>& wall_seconds);

}  // namespace membra
