#pragma once
// Is an equilibrium stable? A soft saddle also has tiny forces, so a small residual does not
// tell. The test is Sylvester's: the Hessian of the energy over the free coordinates, shifted by
// a tiny positive amount, has a Cholesky factorization exactly when its smallest eigenvalue lies
// above minus that amount. Rigid motions of a free sheet (zero eigenvalues) pass.
#include <string>

#include "membra/model/model.hpp"

namespace membra {

struct StabilityReport {
  bool checked = false;  // false when the sheet is too large for the check (see below)
  bool stable = false;
  double shift = 0.0;           // N/m: H + shift I was tested; the tolerance of "stable"
  double min_eigenvalue = 0.0;  // N/m, upper bound when unstable (in (lower, upper]), else 0
  double lower_bound = 0.0;     // N/m, when unstable
  double seconds = 0.0;
  std::string message;
};

// `stiffness` (N/m, normally k_stretch) sets the shift: 1e-6 x stiffness. Sheets of more than
// `max_particles` are not checked (a sparse factorization per test; docs/performance.md).
StabilityReport check_stability(const Model& model, const Points& x, double stiffness,
                                int max_particles = 300000);

}  // namespace membra
