#pragma once
// The signed dihedral angle of a hinge and its gradient. Triangles T1 = (x0, x1, x2) and
// T2 = (x1, x0, x3) are both counter-clockwise seen from +z in the flat sheet. theta is the
// angle between their normals, positive when the hinge folds like a valley seen from the
// normal side (a bowl opening towards +z), negative for a ridge (a dome bulging towards +z).
// Gradient: moving an opposite vertex along its triangle's normal by d turns that triangle by
// d / h (h its height over the edge); the edge vertices take what keeps the angle invariant
// under translations and rotations (Bridson et al. 2003).
#include <array>
#include <cmath>

#include "membra/core/vec.hpp"

namespace membra {

struct HingeEval {
  double theta = 0.0;
  std::array<Vec3, 4> grad;  // d theta / d x_i
};

inline HingeEval hinge_eval(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3) {
  HingeEval r;
  const Vec3 e = x1 - x0;
  const Vec3 n1 = e.cross(x2 - x0);
  const Vec3 n2 = (x0 - x1).cross(x3 - x1);
  const double ee = e.squaredNorm(), a1 = n1.squaredNorm(), a2 = n2.squaredNorm();
  if (ee <= 0.0 || a1 <= 0.0 || a2 <= 0.0) {  // a degenerate triangle has no normal
    for (auto& g : r.grad) g.setZero();
    return r;
  }
  const double le = std::sqrt(ee);
  r.theta = std::atan2(n2.cross(n1).dot(e) / le, n1.dot(n2));
  const Vec3 g2 = (le / a1) * n1, g3 = (le / a2) * n2;
  const double t2 = (x2 - x0).dot(e) / ee, t3 = (x3 - x0).dot(e) / ee;
  r.grad[0] = -(1.0 - t2) * g2 - (1.0 - t3) * g3;
  r.grad[1] = -t2 * g2 - t3 * g3;
  r.grad[2] = g2;
  r.grad[3] = g3;
  return r;
}

// The gradient of theta above, over any scalar type (double, or a forward-mode dual number for
// the Hessian): the 12 entries (d theta / d x0, ..., d theta / d x3). Zero where hinge_eval's is.
template <typename T>
std::array<Eigen::Matrix<T, 3, 1>, 4> hinge_theta_gradient(
    const std::array<Eigen::Matrix<T, 3, 1>, 4>& x) {
  using V = Eigen::Matrix<T, 3, 1>;
  const V e = x[1] - x[0];
  const V n1 = e.cross(x[2] - x[0]);
  const V n2 = (x[0] - x[1]).cross(x[3] - x[1]);
  const T ee = e.squaredNorm(), a1 = n1.squaredNorm(), a2 = n2.squaredNorm();
  std::array<V, 4> g;
  if (ee <= 0.0 || a1 <= 0.0 || a2 <= 0.0) {
    for (auto& gi : g) gi.setZero();
    return g;
  }
  using std::sqrt;
  const T le = sqrt(ee);
  const V g2 = (le / a1) * n1, g3 = (le / a2) * n2;
  const T t2 = (x[2] - x[0]).dot(e) / ee, t3 = (x[3] - x[0]).dot(e) / ee;
  g[0] = -(T(1.0) - t2) * g2 - (T(1.0) - t3) * g3;
  g[1] = -t2 * g2 - t3 * g3;
  g[2] = g2;
  g[3] = g3;
  return g;
}

// Hessian of theta over (x0, x1, x2, x3), 12 x 12, 1/m^2: the exact derivative of the analytic
// gradient above, taken in one forward-mode pass with 12-component dual numbers (no
// differencing step, so exact to round-off), times `moment` (so the Hessian of the hinge's
// energy), symmetrized; with `project` the closest positive semi-definite matrix. Defined in
// hinge_kernel.cpp: the dual numbers are costly to compile, once is enough.
using HingeHessian = Eigen::Matrix<double, 12, 12>;
HingeHessian hinge_hessian(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3,
                           double moment, bool project = false);

}  // namespace membra
