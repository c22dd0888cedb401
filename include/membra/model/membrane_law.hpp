#pragma once
// Hyperelastic laws of a thin sheet in plane stress, as strain energy per unit rest volume W of
// the in-plane right Cauchy-Green tensor C = F^T F (2 x 2, F the 3 x 2 deformation gradient of a
// triangle from its rest shape). An isotropic law of a membrane depends on C through its two
// invariants I = tr C = l1^2 + l2^2 and J = det C = (l1 l2)^2 (l1, l2 the principal stretches),
// so each law here is W(I, J) with its two derivatives (docs/model.md, "The continuum shell"):
//  - neo_hookean: incompressible, the thickness stretch l3 = 1 / (l1 l2) eliminated:
//    W = mu/2 (I + 1/J - 3), mu = E/3 (latex);
//  - mooney_rivlin: incompressible, W = C1 (I + 1/J - 3) + C2 (I/J + J - 3), mu = 2 (C1 + C2);
//  - stvk: Saint Venant-Kirchhoff, W = lambda/2 (tr E)^2 + mu tr(E^2), E = (C - I)/2, with the
//    plane-stress lambda = E nu / (1 - nu^2), mu = E / (2 (1 + nu)) (the resin composite);
//  - linear: the same moduli on the Biot strain U - I, U = sqrt(C): stress proportional to
//    stretch, the linear springs' law, for comparison.
// An incompressible law may be relaxed (tension-field theory, Pipkin 1986/1994): thin latex
// cannot carry compression, it wrinkles at a scale below any practical mesh, so the relaxed
// energy is the least the law stores over every finer wrinkling of the same mean stretch:
//  - slack (l1 <= 1): nothing;
//  - wrinkled (l1 > 1, l2 below uniaxial tension's free stretch l1^-1/2): uniaxial tension
//    at l1, W(l1^2 + 1/l1, l1) in (I, J);
//  - taut: the law itself.
// The three meet with their first derivatives (the free axis's stress is zero where they meet),
// and a small share `kRelaxedResidual` of the law itself keeps slack latex from floating freely.
// Templated on the scalar so that dual numbers give exact second derivatives.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>

namespace membra {

enum class MembraneLaw : std::uint8_t { neo_hookean, mooney_rivlin, stvk, linear };
// How a material's membrane takes compression: as the law says ("full"), or relaxed by
// tension-field theory ("relaxed"; incompressible laws only).
enum class Wrinkling : std::uint8_t { full, relaxed };

std::string_view to_string(MembraneLaw law);
// The law a scene names ("neo_hookean", "mooney_rivlin", "stvk", "linear"), or nothing.
std::optional<MembraneLaw> membrane_law_from_name(std::string_view name);
std::string_view to_string(Wrinkling w);
std::optional<Wrinkling> wrinkling_from_name(std::string_view name);
// Whether `law` can be relaxed (its uniaxial free stretch is l^-1/2: the incompressible laws).
bool relaxable(MembraneLaw law);

// A law and its constants (Pa): neo_hookean c1 = mu; mooney_rivlin c1 = C1, c2 = C2; stvk and
// linear c1 = mu, c2 = the plane-stress lambda.
struct LawConstants {
  MembraneLaw law = MembraneLaw::neo_hookean;
  double c1 = 0.0, c2 = 0.0;
  bool relaxed = false;  // tension-field relaxation (relaxable laws only)
};

// The share of the unrelaxed law a relaxed membrane keeps, so that slack latex still has a
// little stiffness and Newton's matrix stays regular (docs/model.md, "Wrinkling").
inline constexpr double kRelaxedResidual = 1e-3;

// The shape of Mooney-Rivlin's fit to Treloar's uniaxial and equibiaxial rubber over stretches
// 1.0-2.0, C2 / C1 (rubber_fit.hpp; the test refits it from the data; docs/model.md).
inline constexpr double kMooneyRivlinRatio = 0.046;

// The constants of `law` for a material of small-strain Young's modulus E (Pa) and Poisson
// ratio nu (the incompressible laws take nu = 1/2 whatever is given). Throws
// std::invalid_argument for E <= 0 or, for stvk and linear, nu outside [0, 1/2).
LawConstants law_constants(MembraneLaw law, double youngs_modulus, double nu = 1.0 / 3.0);

// W and its partial derivatives in I and J (Pa).
template <typename T>
struct LawValue {
  T w, w_i, w_j;
};

// A scalar's plain value, through any nesting of dual numbers.
template <typename T>
double plain_value(const T& x) {
  if constexpr (std::is_arithmetic_v<T>)
    return static_cast<double>(x);
  else
    return plain_value(x.value());
}

// The law as it is, compression and all.
template <typename T>
LawValue<T> full_strain_energy(const LawConstants& k, const T& I, const T& J) {
  using std::sqrt;
  switch (k.law) {
    case MembraneLaw::neo_hookean: {
      const T inv_j = T(1.0) / J;
      return {0.5 * k.c1 * (I + inv_j - 3.0), T(0.5 * k.c1), -0.5 * k.c1 * inv_j * inv_j};
    }
    case MembraneLaw::mooney_rivlin: {
      const T inv_j = T(1.0) / J;
      return {k.c1 * (I + inv_j - 3.0) + k.c2 * (I * inv_j + J - 3.0), k.c1 + k.c2 * inv_j,
              -(k.c1 + k.c2 * I) * inv_j * inv_j + k.c2};
    }
    case MembraneLaw::stvk: {
      const double mu = k.c1, lambda = k.c2;
      const T tr_e = 0.5 * (I - 2.0);
      return {0.5 * lambda * tr_e * tr_e + 0.25 * mu * (I * I - 2.0 * J - 2.0 * I + 2.0),
              0.5 * lambda * tr_e + 0.5 * mu * (I - 1.0), T(-0.5 * mu)};
    }
    case MembraneLaw::linear: {
      // tr U = sqrt(I + 2 sqrt(J)) (a 2 x 2 identity), |U - I|^2 = I - 2 tr U + 2.
      const double mu = k.c1, lambda = k.c2;
      const T s = sqrt(J), u = sqrt(I + 2.0 * s);
      const T dw_du = -2.0 * mu + lambda * (u - 2.0);
      return {mu * (I - 2.0 * u + 2.0) + 0.5 * lambda * (u - 2.0) * (u - 2.0),
              mu + dw_du / (2.0 * u), dw_du / (2.0 * u * s)};
    }
  }
  return {T(0.0), T(0.0), T(0.0)};
}

// Tension-field theory's relaxed energy of an incompressible law, without the residual, given
// the law's own value at (I, J) (what the taut state stores), so that it is computed once.
template <typename T>
LawValue<T> relaxed_strain_energy(const LawConstants& k, const T& I, const T& J,
                                  const LawValue<T>& full) {
  using std::sqrt;
  const double i = plain_value(I), j = plain_value(J);
  const double big = 0.5 * i + std::sqrt(std::max(0.0, 0.25 * i * i - j));  // l1^2
  if (big <= 1.0) return {T(0.0), T(0.0), T(0.0)};                          // slack
  if (j * j >= big) return full;                                            // taut: l2^2 >= 1/l1
  // Wrinkled: l2 < l1^-1/2 < 1 < l1, so the eigenvalues are apart and s > 0.
  const T s = sqrt(0.25 * I * I - J), l1_sq = 0.5 * I + s, l1 = sqrt(l1_sq);
  const LawValue<T> u = full_strain_energy(k, T(l1_sq + 1.0 / l1), l1);
  // d W / d l1^2 along uniaxial tension, then l1^2's derivatives in I and J.
  const T dw = u.w_i * (1.0 - 0.5 / (l1_sq * l1)) + u.w_j * (0.5 / l1);
  return {u.w, dw * (0.5 + 0.25 * I / s), dw * (-0.5 / s)};
}

template <typename T>
LawValue<T> relaxed_strain_energy(const LawConstants& k, const T& I, const T& J) {
  return relaxed_strain_energy(k, I, J, full_strain_energy(k, I, J));
}

// The law's strain energy: as it is, or relaxed with its residual share.
template <typename T>
LawValue<T> strain_energy(const LawConstants& k, const T& I, const T& J) {
  if (!k.relaxed) return full_strain_energy(k, I, J);
  const LawValue<T> f = full_strain_energy(k, I, J), r = relaxed_strain_energy(k, I, J, f);
  return {r.w + kRelaxedResidual * f.w, r.w_i + kRelaxedResidual * f.w_i,
          r.w_j + kRelaxedResidual * f.w_j};
}

// Nominal stress (force per undeformed area, Pa) of the law in uniaxial tension at stretch l
// (the other in-plane axis free, its stretch from d W / d l2 = 0) and in equibiaxial tension at
// stretch l on both axes: the closed forms the tests hold the membrane to.
double uniaxial_nominal_stress(const LawConstants& k, double l);
double equibiaxial_nominal_stress(const LawConstants& k, double l);
// The free axis's stretch in uniaxial tension at l.
double uniaxial_lateral_stretch(const LawConstants& k, double l);

}  // namespace membra
