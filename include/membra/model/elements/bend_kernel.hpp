#pragma once
// One bending element: three consecutive particles x0, x1, x2 along a grid line or diagonal.
// With a = x1 - x0, b = x2 - x1 and psi the turning angle between them, the energy is
//   E = 4 c tan^2(psi / 2) = 4 c (|a|^2 |b|^2 - (a.b)^2) / (|a||b| + a.b)^2,
// which is c psi^2 for small angles. 2 tan(psi/2) is the discrete curvature binormal of discrete
// elastic rods (Bergou et al. 2008); written with dot products only, it is smooth at psi = 0
// (a straight line) and cheap. It grows without bound as the line folds back (psi -> pi).
#include <array>
#include <cmath>

#include "membra/core/vec.hpp"
#include "membra/model/psd_projection.hpp"

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

// Hessian of the bending element's energy over (x0, x1, x2), 9 x 9, J/m^2. With u = |a|^2,
// v = |b|^2, w = a.b and r = sqrt(u v), the energy is E = 4 c (r - w) / (r + w) (the same
// tan^2(psi/2) as above, since |a x b|^2 = (r - w)(r + w)); the Hessian follows by the chain rule
// through (u, v, w), whose own second derivatives are constant (docs/solver.md). Zero where
// bend_eval's gradient is zero.
using BendHessian = Eigen::Matrix<double, 9, 9>;
inline BendHessian bend_hessian(const Vec3& x0, const Vec3& x1, const Vec3& x2, double c,
                                bool project = false) {
  const Vec3 a = x1 - x0, b = x2 - x1;
  const double u = a.squaredNorm(), v = b.squaredNorm(), w = a.dot(b);
  const double r = std::sqrt(u * v), d = r + w;
  BendHessian h = BendHessian::Zero();
  if (r <= 0.0 || d <= 0.0) return h;
  const double d2 = d * d, d3 = d2 * d;
  // E(r, w) and its derivatives.
  const double e_r = 8.0 * c * w / d2, e_w = -8.0 * c * r / d2;
  const double e_rr = -16.0 * c * w / d3, e_ww = 16.0 * c * r / d3, e_rw = 8.0 * c * (r - w) / d3;
  // r(u, v) and its derivatives.
  const double r_u = v / (2.0 * r), r_v = u / (2.0 * r);
  const double r_uu = -v * v / (4.0 * r * r * r), r_vv = -u * u / (4.0 * r * r * r),
               r_uv = 1.0 / (4.0 * r);
  const double e_u = e_r * r_u, e_v = e_r * r_v;
  Eigen::Matrix3d s;  // second derivatives of E over (u, v, w)
  s(0, 0) = e_rr * r_u * r_u + e_r * r_uu;
  s(1, 1) = e_rr * r_v * r_v + e_r * r_vv;
  s(0, 1) = s(1, 0) = e_rr * r_u * r_v + e_r * r_uv;
  s(0, 2) = s(2, 0) = e_rw * r_u;
  s(1, 2) = s(2, 1) = e_rw * r_v;
  s(2, 2) = e_ww;
  Eigen::Matrix<double, 3, 6> j;  // gradients of u, v, w over (a, b)
  j << 2.0 * a.transpose(), Eigen::RowVector3d::Zero(), Eigen::RowVector3d::Zero(),
      2.0 * b.transpose(), b.transpose(), a.transpose();
  Eigen::Matrix<double, 6, 6> hab = j.transpose() * s * j;
  const Eigen::Matrix3d id = Eigen::Matrix3d::Identity();
  hab.topLeftCorner<3, 3>() += 2.0 * e_u * id;
  hab.bottomRightCorner<3, 3>() += 2.0 * e_v * id;
  hab.topRightCorner<3, 3>() += e_w * id;
  hab.bottomLeftCorner<3, 3>() += e_w * id;
  if (project) hab = project_psd(hab);
  // (a, b) = T x with a = x1 - x0, b = x2 - x1.
  Eigen::Matrix<double, 6, 9> t = Eigen::Matrix<double, 6, 9>::Zero();
  t.block<3, 3>(0, 0) = -id;
  t.block<3, 3>(0, 3) = id;
  t.block<3, 3>(3, 3) = -id;
  t.block<3, 3>(3, 6) = id;
  h = t.transpose() * hab * t;
  return h;
}

}  // namespace membra
