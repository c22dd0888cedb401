#pragma once
// One spring's energy and force: the single kernel that every force pass, energy sum and
// measure uses, so energies and forces cannot disagree.
#include <array>
#include <cmath>
#include <string_view>

#include "membra/core/vec.hpp"
#include "membra/model/elements/element_set.hpp"
#include "membra/model/elements/set_context.hpp"

namespace membra {

// A spring's read-out (element_set.hpp): strain (l - l0) / l0, force k (l - l0), and the stress
// force / (width x thickness) where its tributary width is known.
inline ElementStress axial_stress(const Vec3& xa, const Vec3& xb, double l0, double k, double width,
                                  double thickness) {
  const double l = (xb - xa).norm();
  ElementStress e;
  e.strained = true;
  e.strain = l0 > 0.0 ? (l - l0) / l0 : 0.0;
  e.axial = true;
  e.force = k * (l - l0);
  if (!(width > 0.0)) return e;
  e.carries = true;
  e.stress = thickness > 0.0 ? k * (l - l0) / (width * thickness) : 0.0;
  return e;
}

// Elastic energy 1/2 k (l - l0)^2 of a spring between xa and xb (J for SI inputs).
inline double spring_energy(const Vec3& xa, const Vec3& xb, double l0, double k) {
  const double stretch = (xb - xa).norm() - l0;
  return 0.5 * k * stretch * stretch;
}

// Force on particle a (the force on b is its negative): the elastic part k (l - l0) along the
// unit vector from a to b, plus damping c times the relative velocity along the spring.
// A spring of zero length has no direction and exerts no force.
inline Vec3 spring_force_on_a(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb,
                              double l0, double k, double c) {
  const Vec3 d = xb - xa;
  const double l = d.norm();
  if (l <= 0.0) return Vec3::Zero();
  const Vec3 n = d / l;
  const double closing_speed = (vb - va).dot(n);
  return (k * (l - l0) + c * closing_speed) * n;
}

// The elastic part alone, k (1 - l0/l) (xb - xa): the same force as spring_force_on_a with no
// damping, in one square root and one division (the static solvers' force passes are half of
// their time in this line).
inline Vec3 spring_static_force_on_a(const Vec3& xa, const Vec3& xb, double l0, double k) {
  const Vec3 d = xb - xa;
  const double l = d.norm();
  if (l <= 0.0) return Vec3::Zero();
  return (k * (1.0 - l0 / l)) * d;
}

// Hessian block K of a spring's energy (3 x 3, N/m): d^2E/dxa^2 = d^2E/dxb^2 = K and
// d^2E/dxa dxb = -K, with K = k [n n^T + g (I - n n^T)], n the unit vector a -> b and
// g = 1 - l0/l the geometric (stress) part, negative when the spring is compressed. With
// `project` g is clamped at zero: the closest positive semi-definite element Hessian.
inline Eigen::Matrix3d spring_hessian_block(const Vec3& xa, const Vec3& xb, double l0, double k,
                                            bool project = false) {
  const Vec3 d = xb - xa;
  const double l = d.norm();
  if (l <= 0.0) return Eigen::Matrix3d::Zero();
  const Vec3 n = d / l;
  double g = 1.0 - l0 / l;
  if (project && g < 0.0) g = 0.0;
  return k * ((1.0 - g) * n * n.transpose() + g * Eigen::Matrix3d::Identity());
}

// The spring's whole Hessian (6 x 6, particles a then b) from its block.
inline Eigen::Matrix<double, 6, 6> spring_hessian(const Vec3& xa, const Vec3& xb, double l0,
                                                  double k, bool project) {
  const Eigen::Matrix3d h = spring_hessian_block(xa, xb, l0, k, project);
  Eigen::Matrix<double, 6, 6> block;
  block << h, -h, -h, h;
  return block;
}

// Forces of springs [begin, end) of parallel arrays (particles a, b; rest lengths, stiffnesses
// and dampings) added into f: with velocities v the damped kernel, without them the lean static
// one (2x faster). Both spring sets' force pass.
template <typename Ids, typename Values>
void add_spring_forces(const Ids& a, const Ids& b, const Values& rest, const Values& k,
                       const Values& damping, const Points& x, const Points* v, int begin, int end,
                       Points& f) {
  if (!v) {
    for (int i = begin; i < end; ++i) {
      const int pa = a[i], pb = b[i];
      const Vec3 fa = spring_static_force_on_a(x.col(pa), x.col(pb), rest[i], k[i]);
      f.col(pa) += fa;
      f.col(pb) -= fa;
    }
    return;
  }
  for (int i = begin; i < end; ++i) {
    const int pa = a[i], pb = b[i];
    const Vec3 fa =
        spring_force_on_a(x.col(pa), x.col(pb), v->col(pa), v->col(pb), rest[i], k[i], damping[i]);
    f.col(pa) += fa;
    f.col(pb) -= fa;
  }
}

// Both spring sets' growth rule: the growth of the spring between particles pa and pb read from
// the field at their paper positions, and the length ratio that growth gives it.
inline LocalGrowth segment_growth(const GrowthField& field, const Points& paper, int pa, int pb,
                                  std::string_view group) {
  const std::array<int, 2> id = {pa, pb};
  const std::array<Vec2, 2> p = {paper.col(pa).head<2>(), paper.col(pb).head<2>()};
  return field.at(id, p, group);
}
inline double segment_ratio(const LocalGrowth& g, const Points& paper, int pa, int pb) {
  return g.ratio(paper.col(pb).head<2>() - paper.col(pa).head<2>());
}

// A diagonal stiffness for each end (N/m, the static solver's masses): the axial stiffness k plus
// the geometric (stress) stiffness |k (1 - l0/l)| across the spring.
inline double spring_stiffness_estimate(const Vec3& xa, const Vec3& xb, double l0, double k) {
  const double l = (xb - xa).norm();
  return k * (1.0 + (l > 0.0 ? std::abs(1.0 - l0 / l) : 1.0));
}

}  // namespace membra
