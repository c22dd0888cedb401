#pragma once
// One bending element: three consecutive particles x0, x1, x2 along a grid line or diagonal.
// With a = x1 - x0, b = x2 - x1 and psi the turning angle between them, the energy is
//   E = 4 c tan^2(psi / 2) = 4 c (|a|^2 |b|^2 - (a.b)^2) / (|a||b| + a.b)^2,
// which is c psi^2 for small angles. 2 tan(psi/2) is the discrete curvature binormal of discrete
// elastic rods (Bergou et al. 2008); written with dot products only, it is smooth at psi = 0
// (a straight line) and cheap. It grows without bound as the line folds back (psi -> pi).
#include <array>

#include "membra/core/vec.hpp"

namespace membra {

struct BendEval {
  double energy = 0.0;
  std::array<Vec3, 3> grad;  // dE / dx_i
};

inline BendEval bend_eval(const Vec3& x0, const Vec3& x1, const Vec3& x2, double c) {
  BendEval r;
  const Vec3 a = x1 - x0, b = x2 - x1;
  const double aa = a.squaredNorm(), bb = b.squaredNorm(), ab = a.dot(b);
  // |a||b| from one square root; lb/la = bb/(la lb) and la/lb = aa/(la lb): one root and two
  // divisions per element instead of two and four (this kernel dominates a sheet's force pass).
  const double lalb = std::sqrt(aa * bb);
  const double d = lalb + ab;
  if (lalb <= 0.0 || d <= 0.0) {  // coincident particles or folded flat back
    for (auto& g : r.grad) g.setZero();
    return r;
  }
  const double p = aa * bb - ab * ab;  // |a x b|^2
  const double inv_d = 1.0 / d, inv_d2 = inv_d * inv_d, inv_lalb = 1.0 / lalb;
  r.energy = 4.0 * c * p * inv_d2;
  const double q = 2.0 * p * inv_d2 * inv_d;
  const Vec3 g_a = 4.0 * c * ((2.0 * bb * a - 2.0 * ab * b) * inv_d2 - q * (bb * inv_lalb * a + b));
  const Vec3 g_b = 4.0 * c * ((2.0 * aa * b - 2.0 * ab * a) * inv_d2 - q * (aa * inv_lalb * b + a));
  r.grad[0] = -g_a;
  r.grad[1] = g_a - g_b;
  r.grad[2] = g_b;
  return r;
}

}  // namespace membra
