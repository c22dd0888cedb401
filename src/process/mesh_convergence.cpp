#include "membra/process/mesh_convergence.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace membra {
namespace {

double change(double coarse, double fine) {
  if (fine == 0.0) return coarse == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  return std::abs(fine - coarse) / std::abs(fine);
}

}  // namespace

bool MeshConvergence::passes() const {
  return same_classification && curvature_change <= 0.05 && height_change <= 0.03 &&
         energy_change <= 0.02;
}

std::string MeshConvergence::line() const {
  std::string failing;
  const auto fail = [&](bool bad, const char* what) {
    if (bad) failing += (failing.empty() ? "" : ", ") + std::string(what);
  };
  fail(!same_classification, "classification");
  fail(curvature_change > 0.05, "K");
  fail(height_change > 0.03, "height");
  fail(energy_change > 0.02, "energy");
  char buf[160];
  std::snprintf(buf, sizeof buf, "K %.1f %%, height %.1f %%, energy %.1f %%: %s",
                100.0 * curvature_change, 100.0 * height_change, 100.0 * energy_change,
                passes() ? "passes" : "fails");
  return std::string(buf) + (failing.empty() ? "" : " (" + failing + ")");
}

MeshConvergence compare_meshes(const FormReading& coarse, const FormReading& fine) {
  MeshConvergence m;
  m.same_classification = coarse.classification == fine.classification;
  m.curvature_change = change(coarse.total_curvature, fine.total_curvature);
  m.height_change = change(coarse.height, fine.height);
  m.energy_change = change(coarse.energy, fine.energy);
  return m;
}

double cost_exponent(const std::vector<int>& vertices, const std::vector<double>& wall_seconds) {
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  const double n = static_cast<double>(vertices.size());
  for (size_t k = 0; k < vertices.size(); ++k) {
    const double x = std::log(static_cast<double>(vertices[k]));
    const double y = std::log(wall_seconds[k]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double spread = n * sxx - sx * sx;
  return n < 2.0 || spread <= 1e-12 * n * sxx ? 0.0 : (n * sxy - sx * sy) / spread;
}

}  // namespace membra
