#pragma once
// Fitting a rubber law's constants to measured curves (nominal stress against stretch, uniaxial
// or equibiaxial), by least squares on the relative error so that small stretches count as much
// as large ones. Mooney-Rivlin's nominal stresses are linear in (C1, C2), so its fit is a 2 x 2
// solve; neo-Hookean's is Mooney-Rivlin with C2 = 0. docs/model.md has the fit to Treloar's
// rubber (L. R. G. Treloar 1944, Trans. Faraday Soc. 40, 59-70) and its errors.
#include <vector>

#include "membra/model/membrane_law.hpp"

namespace membra {

struct RubberCurve {
  bool equibiaxial = false;            // else uniaxial
  std::vector<double> stretch;         // 1
  std::vector<double> nominal_stress;  // Pa, force per undeformed area
};

// The constants minimising the mean squared relative error over the points of `curves` with
// stretch <= max_stretch: Mooney-Rivlin (C1, C2), or neo-Hookean (mu) when `neo_hookean`.
// Throws std::invalid_argument when fewer than two points are in range.
LawConstants fit_rubber(const std::vector<RubberCurve>& curves, double max_stretch,
                        bool neo_hookean = false);

// The root-mean-square relative error of `law`'s nominal stress against a curve's points with
// stretch <= max_stretch (1 = 100 %).
double rubber_rms_error(const LawConstants& law, const RubberCurve& curve, double max_stretch);

}  // namespace membra
