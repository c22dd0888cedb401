#pragma once
// The kernel of self-contact (self_contact.hpp): the squared distance D from a point to a
// triangle, and a barrier on it that is zero from the contact gap g outwards and grows without
// bound as the point reaches the triangle, smooth enough for Newton (C2 at D = g^2):
//   b(D) = -(D - g^2)^2 ln(D / g^2)   for D < g^2, else 0
// (the barrier of incremental potential contact, on squared distances). A pair's energy is
// w b(D), its weight w = k A g / g^4 for a pressure scale k (Pa) and the point's share of the
// sheet's area A (m^2), so that the push per area at a gap d is k times a function of d / g
// alone (docs/model.md, "Self-contact").
#include <Eigen/Core>

#include "membra/core/vec.hpp"

namespace membra {

// Which feature of the triangle (a, b, c) is nearest the point: its face, one of its edges
// (ab, bc, ca) or one of its corners.
enum class NearestFeature { face, edge_ab, edge_bc, edge_ca, vertex_a, vertex_b, vertex_c };

struct PointTriangleDistance {
  double d2 = 0.0;  // m^2
  NearestFeature feature = NearestFeature::face;
};

// The squared distance from p to the triangle (a, b, c) and the feature it is measured to.
PointTriangleDistance point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b,
                                              const Vec3& c);

// The barrier b(D) and its first two derivatives in D, for a gap g (gap2 = g^2).
struct BarrierValue {
  double value = 0.0, first = 0.0, second = 0.0;
};
BarrierValue contact_barrier(double d2, double gap2);

using ContactGradient = Eigen::Matrix<double, 12, 1>;
using ContactHessian = Eigen::Matrix<double, 12, 12>;

// The pair's energy w b(D) (J) for the point p and the triangle (a, b, c) (coordinates in that
// order, 12 of them), its gradient (N) and its Hessian (N/m; PSD-projected with `project`).
double contact_energy(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, double weight,
                      double gap2);
ContactGradient contact_gradient(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                                 double weight, double gap2);
ContactHessian contact_hessian(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                               double weight, double gap2, bool project);

}  // namespace membra
