#include "membra/model/membrane_law.hpp"

#include <stdexcept>

namespace membra {

std::string_view to_string(MembraneLaw law) {
  switch (law) {
    case MembraneLaw::neo_hookean:
      return "neo_hookean";
    case MembraneLaw::mooney_rivlin:
      return "mooney_rivlin";
    case MembraneLaw::stvk:
      return "stvk";
    case MembraneLaw::linear:
      return "linear";
  }
  return "unknown";
}

std::optional<MembraneLaw> membrane_law_from_name(std::string_view name) {
  for (MembraneLaw law : {MembraneLaw::neo_hookean, MembraneLaw::mooney_rivlin, MembraneLaw::stvk,
                          MembraneLaw::linear})
    if (to_string(law) == name) return law;
  return std::nullopt;
}

std::string_view to_string(Wrinkling w) {
  return w == Wrinkling::relaxed ? "relaxed" : "full";
}

std::optional<Wrinkling> wrinkling_from_name(std::string_view name) {
  for (Wrinkling w : {Wrinkling::full, Wrinkling::relaxed})
    if (to_string(w) == name) return w;
  return std::nullopt;
}

bool relaxable(MembraneLaw law) {
  return law == MembraneLaw::neo_hookean || law == MembraneLaw::mooney_rivlin;
}

LawConstants law_constants(MembraneLaw law, double youngs_modulus, double nu) {
  if (!(youngs_modulus > 0.0)) throw std::invalid_argument("a law needs a positive modulus E");
  const double mu_incompressible = youngs_modulus / 3.0;
  switch (law) {
    case MembraneLaw::neo_hookean:
      return {law, mu_incompressible, 0.0};
    case MembraneLaw::mooney_rivlin: {
      // mu = 2 (C1 + C2), C2 = ratio C1.
      const double c1 = 0.5 * mu_incompressible / (1.0 + kMooneyRivlinRatio);
      return {law, c1, kMooneyRivlinRatio * c1};
    }
    case MembraneLaw::stvk:
    case MembraneLaw::linear:
      if (!(nu >= 0.0 && nu < 0.5))
        throw std::invalid_argument("stvk and linear laws need a Poisson ratio in [0, 0.5)");
      return {law, youngs_modulus / (2.0 * (1.0 + nu)), youngs_modulus * nu / (1.0 - nu * nu)};
  }
  throw std::invalid_argument("unknown membrane law");
}

namespace {

// d W / d l_a at principal stretches (la, lb): 2 la (W_I + W_J lb^2).
double principal_derivative(const LawConstants& k, double la, double lb) {
  const LawValue<double> v = strain_energy(k, la * la + lb * lb, la * la * lb * lb);
  return 2.0 * la * (v.w_i + v.w_j * lb * lb);
}

}  // namespace

double uniaxial_lateral_stretch(const LawConstants& k, double l) {
  // d W / d l2 = 2 l2 (W_I + W_J l^2) rises through 0 with l2 for every law here: bisect.
  double lo = 1e-6, hi = 10.0;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (principal_derivative(k, mid, l) > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

double uniaxial_nominal_stress(const LawConstants& k, double l) {
  return principal_derivative(k, l, uniaxial_lateral_stretch(k, l));
}

double equibiaxial_nominal_stress(const LawConstants& k, double l) {
  return principal_derivative(k, l, l);
}

}  // namespace membra
