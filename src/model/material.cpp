#include "membra/model/material.hpp"

#include "membra/core/units.hpp"

namespace membra {

Material latex() {
  return {"latex", 1.5 * units::MPa, 0.5 * units::mm, 0.93 * units::g_per_cm3};
}

Material epoxy() {
  return {"epoxy", 2500.0 * units::MPa, 0.5 * units::mm, 1.2 * units::g_per_cm3, MembraneLaw::stvk};
}

std::optional<Material> material_preset(std::string_view name) {
  if (name == "latex") return latex();
  if (name == "epoxy") return epoxy();
  return std::nullopt;
}

LatticeStiffness homogenize(const Material& m, double flex_ratio) {
  const double et = m.youngs_modulus * m.thickness;
  LatticeStiffness k;
  k.shear = 3.0 / 8.0 * et;
  k.stretch = 2.0 * k.shear / (1.0 + 4.0 * flex_ratio);
  k.flex = flex_ratio * k.stretch;
  return k;
}

double membrane_stiffness_from_stretch(double k_stretch, double flex_ratio) {
  return 4.0 / 3.0 * k_stretch * (1.0 + 4.0 * flex_ratio);
}

double bending_stiffness(const Material& m) {
  constexpr double nu = 1.0 / 3.0;
  const double t = m.thickness;
  return m.youngs_modulus * t * t * t / (12.0 * (1.0 - nu * nu));
}

}  // namespace membra
