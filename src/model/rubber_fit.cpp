#include "membra/model/rubber_fit.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>

namespace membra {
namespace {

// The nominal stress's factors of C1 and C2 at stretch l: uniaxial 2 (l - l^-2) (1, 1/l),
// equibiaxial 2 (l - l^-5) (1, l^2) (incompressible, plane stress).
Eigen::Vector2d basis(bool equibiaxial, double l) {
  if (equibiaxial) {
    const double a = 2.0 * (l - std::pow(l, -5.0));
    return {a, a * l * l};
  }
  const double a = 2.0 * (l - 1.0 / (l * l));
  return {a, a / l};
}

double nominal(const LawConstants& law, bool equibiaxial, double l) {
  return equibiaxial ? equibiaxial_nominal_stress(law, l) : uniaxial_nominal_stress(law, l);
}

}  // namespace

LawConstants fit_rubber(const std::vector<RubberCurve>& curves, double max_stretch,
                        bool neo_hookean) {
  Eigen::Matrix2d ata = Eigen::Matrix2d::Zero();
  Eigen::Vector2d atb = Eigen::Vector2d::Zero();
  int points = 0;
  for (const RubberCurve& c : curves)
    for (size_t k = 0; k < c.stretch.size(); ++k) {
      if (c.stretch[k] > max_stretch) continue;
      Eigen::Vector2d row = basis(c.equibiaxial, c.stretch[k]) / c.nominal_stress[k];
      if (neo_hookean) row[1] = 0.0;
      ata += row * row.transpose();
      atb += row;  // the target of each row is 1: measured / measured
      ++points;
    }
  if (points < 2) throw std::invalid_argument("a rubber fit needs two points in range at least");
  if (neo_hookean) return {MembraneLaw::neo_hookean, 2.0 * atb[0] / ata(0, 0), 0.0};
  const Eigen::Vector2d c = ata.ldlt().solve(atb);
  return {MembraneLaw::mooney_rivlin, c[0], c[1]};
}

double rubber_rms_error(const LawConstants& law, const RubberCurve& curve, double max_stretch) {
  double sum = 0.0;
  int n = 0;
  for (size_t k = 0; k < curve.stretch.size(); ++k) {
    if (curve.stretch[k] > max_stretch) continue;
    const double rel = nominal(law, curve.equibiaxial, curve.stretch[k]) / curve.nominal_stress[k];
    sum += (rel - 1.0) * (rel - 1.0);
    ++n;
  }
  return n > 0 ? std::sqrt(sum / n) : 0.0;
}

}  // namespace membra
