#include "membra/model/bilayer.hpp"

#include <stdexcept>

namespace membra {
double bilayer_curvature_per_strain(const Material& base, const Material& layer) {
  if (!(base.thickness > 0.0) || !(layer.thickness > 0.0) || !(base.youngs_modulus > 0.0) ||
      !(layer.youngs_modulus > 0.0))
    throw std::invalid_argument("bilayer: both materials need a positive thickness and modulus");
  const double m = layer.thickness / base.thickness;
  const double n = layer.youngs_modulus / base.youngs_modulus;
  const double t = 6.0 * (1.0 + m) * (1.0 + m) /
                   (3.0 * (1.0 + m) * (1.0 + m) + (1.0 + m * n) * (m * m + 1.0 / (m * n)));
  return t / (base.thickness + layer.thickness);
}

}  // namespace membra
