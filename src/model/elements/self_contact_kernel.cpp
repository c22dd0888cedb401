#include "membra/model/elements/self_contact_kernel.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include <unsupported/Eigen/AutoDiff>

#include "membra/model/psd_projection.hpp"

namespace membra {
namespace {

template <typename T>
using V3 = std::array<T, 3>;

template <typename T>
V3<T> sub(const V3<T>& u, const V3<T>& v) {
  return {u[0] - v[0], u[1] - v[1], u[2] - v[2]};
}
template <typename T>
T dot(const V3<T>& u, const V3<T>& v) {
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}
template <typename T>
V3<T> cross(const V3<T>& u, const V3<T>& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

// D for a fixed nearest feature, in any scalar (doubles, or dual numbers for the derivatives):
// to the face's plane, to an edge's line, or to a corner. x holds p, a, b, c.
template <typename T>
T feature_d2(NearestFeature f, const std::array<V3<T>, 4>& x) {
  const V3<T>&p = x[0], &a = x[1], &b = x[2], &c = x[3];
  auto to_line = [&](const V3<T>& u, const V3<T>& v) {
    const V3<T> e = sub(v, u), w = cross(sub(p, u), e);
    return dot(w, w) / dot(e, e);
  };
  auto to_point = [&](const V3<T>& u) {
    const V3<T> w = sub(p, u);
    return dot(w, w);
  };
  switch (f) {
    case NearestFeature::face: {
      const V3<T> n = cross(sub(b, a), sub(c, a));
      const T h = dot(sub(p, a), n);
      return h * h / dot(n, n);
    }
    case NearestFeature::edge_ab:
      return to_line(a, b);
    case NearestFeature::edge_bc:
      return to_line(b, c);
    case NearestFeature::edge_ca:
      return to_line(c, a);
    case NearestFeature::vertex_a:
      return to_point(a);
    case NearestFeature::vertex_b:
      return to_point(b);
    case NearestFeature::vertex_c:
      return to_point(c);
  }
  return to_point(a);
}

// The nearest feature of a triangle of no area (corners in a line or together): the nearest of
// its corners and of its edges of some length whose nearest point lies inside them.
NearestFeature nearest_of_collapsed(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const std::array<Vec3, 3> v = {a, b, c};
  const std::array<NearestFeature, 3> corner = {NearestFeature::vertex_a, NearestFeature::vertex_b,
                                                NearestFeature::vertex_c};
  const std::array<NearestFeature, 3> edge = {NearestFeature::edge_ab, NearestFeature::edge_bc,
                                              NearestFeature::edge_ca};
  NearestFeature best = NearestFeature::vertex_a;
  double d = INFINITY;
  for (size_t k = 0; k < 3; ++k) {
    if (const double dk = (p - v[k]).squaredNorm(); dk < d) d = dk, best = corner[k];
    const Vec3 e = v[(k + 1) % 3] - v[k];
    const double len2 = e.squaredNorm();
    if (!(len2 > 0.0)) continue;
    const double t = (p - v[k]).dot(e) / len2;
    if (!(t > 0.0 && t < 1.0)) continue;
    if (const double de = (p - v[k] - t * e).squaredNorm(); de < d) d = de, best = edge[k];
  }
  return best;
}

// The nearest feature by the regions of the triangle's plane (Ericson, Real-Time Collision
// Detection, 5.1.5); a triangle of no area by its edges and corners only.
NearestFeature nearest_feature(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  if (!(ab.cross(ac).squaredNorm() > 1e-24 * ab.squaredNorm() * ac.squaredNorm()) ||
      !(ab.squaredNorm() > 0.0) || !(ac.squaredNorm() > 0.0))
    return nearest_of_collapsed(p, a, b, c);
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return NearestFeature::vertex_a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return NearestFeature::vertex_b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return NearestFeature::edge_ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return NearestFeature::vertex_c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return NearestFeature::edge_ca;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return NearestFeature::edge_bc;
  return NearestFeature::face;
}

// The weights of the triangle's corners in its point nearest p, on the nearest feature f.
std::array<double, 3> nearest_weights(NearestFeature f, const Vec3& p, const Vec3& a, const Vec3& b,
                                      const Vec3& c) {
  auto along = [&](const Vec3& u, const Vec3& v) {  // share of v on the segment u-v
    const double len2 = (v - u).squaredNorm();
    return len2 > 0.0 ? std::clamp((p - u).dot(v - u) / len2, 0.0, 1.0) : 0.0;
  };
  switch (f) {
    case NearestFeature::face: {
      const Vec3 ab = b - a, ac = c - a, ap = p - a;
      const double d00 = ab.dot(ab), d01 = ab.dot(ac), d11 = ac.dot(ac);
      const double det = d00 * d11 - d01 * d01;
      const double s = (d11 * ab.dot(ap) - d01 * ac.dot(ap)) / det;
      const double t = (d00 * ac.dot(ap) - d01 * ab.dot(ap)) / det;
      return {1.0 - s - t, s, t};
    }
    case NearestFeature::edge_ab: {
      const double t = along(a, b);
      return {1.0 - t, t, 0.0};
    }
    case NearestFeature::edge_bc: {
      const double t = along(b, c);
      return {0.0, 1.0 - t, t};
    }
    case NearestFeature::edge_ca: {
      const double t = along(c, a);
      return {t, 0.0, 1.0 - t};
    }
    case NearestFeature::vertex_a:
      return {1.0, 0.0, 0.0};
    case NearestFeature::vertex_b:
      return {0.0, 1.0, 0.0};
    case NearestFeature::vertex_c:
      return {0.0, 0.0, 1.0};
  }
  return {1.0, 0.0, 0.0};
}

std::array<V3<double>, 4> as_arrays(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  return {
      {{p.x(), p.y(), p.z()}, {a.x(), a.y(), a.z()}, {b.x(), b.y(), b.z()}, {c.x(), c.y(), c.z()}}};
}

// The weights of the corners in the nearest point on feature f, as dual numbers: on a face its
// barycentric coordinates, on an edge the share along it (the region fixes which, so no clamp).
// A weight that is exactly 0 or 1 is kept as a number: a dual number made from a constant is
// what GCC's uninitialised-use analysis cannot follow through Eigen's AutoDiff.
using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, 12, 1>>;
struct DualWeight {
  enum { zero, one, dual } kind = zero;
  std::optional<Dual> w;  // only for kind dual
};

std::array<DualWeight, 3> weights_on(NearestFeature f, const std::array<V3<Dual>, 4>& x) {
  const V3<Dual>&p = x[0], &a = x[1], &b = x[2], &c = x[3];
  auto along = [&](const V3<Dual>& u, const V3<Dual>& v) {  // share of v on the line u-v
    const V3<Dual> e = sub(v, u);
    return Dual(dot(sub(p, u), e) / dot(e, e));
  };
  auto dual = [](const Dual& w) { return DualWeight{DualWeight::dual, w}; };
  const DualWeight zero{}, one{DualWeight::one, std::nullopt};
  switch (f) {
    case NearestFeature::face: {
      const V3<Dual> ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
      const Dual d00 = dot(ab, ab), d01 = dot(ab, ac), d11 = dot(ac, ac);
      const Dual det = d00 * d11 - d01 * d01;
      const Dual s = (d11 * dot(ab, ap) - d01 * dot(ac, ap)) / det;
      const Dual t = (d00 * dot(ac, ap) - d01 * dot(ab, ap)) / det;
      return {dual(1.0 - (s + t)), dual(s), dual(t)};
    }
    case NearestFeature::edge_ab: {
      const Dual t = along(a, b);
      return {dual(1.0 - t), dual(t), zero};
    }
    case NearestFeature::edge_bc: {
      const Dual t = along(b, c);
      return {zero, dual(1.0 - t), dual(t)};
    }
    case NearestFeature::edge_ca: {
      const Dual t = along(c, a);
      return {dual(t), zero, dual(1.0 - t)};
    }
    case NearestFeature::vertex_a:
      return {one, zero, zero};
    case NearestFeature::vertex_b:
      return {zero, one, zero};
    case NearestFeature::vertex_c:
      return {zero, zero, one};
  }
  return {one, zero, zero};
}

// D and its Hessian: the gradient 2 (p - q), -2 w_i (p - q) (q the nearest point, w its
// weights) written in dual numbers of the 12 coordinates, whose derivatives are the Hessian.
struct SecondOrder {
  double d2 = 0.0;
  ContactGradient gradient;
  ContactHessian hessian;
};

SecondOrder second_order(NearestFeature f, const std::array<V3<double>, 4>& x) {
  std::array<V3<Dual>, 4> dx;
  for (int k = 0; k < 12; ++k)
    dx[static_cast<size_t>(k / 3)][static_cast<size_t>(k % 3)] =
        Dual(x[static_cast<size_t>(k / 3)][static_cast<size_t>(k % 3)], 12, k);
  const std::array<DualWeight, 3> w = weights_on(f, dx);
  SecondOrder s;
  s.gradient.setZero();
  s.hessian.setZero();
  for (int c = 0; c < 3; ++c) {
    const size_t cc = static_cast<size_t>(c);
    Dual r = dx[0][cc];  // p - q, q = sum w_k t_k
    for (size_t k = 0; k < 3; ++k) {
      if (w[k].kind == DualWeight::one) r = r - dx[k + 1][cc];
      if (w[k].kind == DualWeight::dual) r = r - *w[k].w * dx[k + 1][cc];
    }
    s.d2 += r.value() * r.value();
    s.gradient[c] = 2.0 * r.value();
    s.hessian.row(c) = 2.0 * r.derivatives().transpose();
    for (size_t k = 0; k < 3; ++k) {
      if (w[k].kind == DualWeight::zero) continue;
      const Dual gk = w[k].kind == DualWeight::one ? Dual(r * -2.0) : Dual(*w[k].w * r * -2.0);
      const int row = 3 + 3 * static_cast<int>(k) + c;
      s.gradient[row] = gk.value();
      s.hessian.row(row) = gk.derivatives().transpose();
    }
  }
  s.hessian = (0.5 * (s.hessian + s.hessian.transpose())).eval();
  return s;
}

}  // namespace

PointTriangleDistance point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b,
                                              const Vec3& c) {
  const NearestFeature f = nearest_feature(p, a, b, c);
  return {feature_d2<double>(f, as_arrays(p, a, b, c)), f};
}

BarrierValue contact_barrier(double d2, double gap2) {
  if (!(d2 < gap2)) return {};
  const double u = d2 - gap2, l = std::log(d2 / gap2);
  return {-u * u * l, -2.0 * u * l - u * u / d2, -2.0 * l - 4.0 * u / d2 + u * u / (d2 * d2)};
}

double contact_energy(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, double weight,
                      double gap2) {
  return weight * contact_barrier(point_triangle_distance(p, a, b, c).d2, gap2).value;
}

// The gradient of D = |p - q|^2, q the nearest point of the triangle, q = sum w_i t_i: since q is
// nearest, moving it along the triangle changes D only to second order, so dD/dp = 2 (p - q) and
// dD/dt_i = -2 w_i (p - q), in every region alike.
ContactGradient contact_gradient(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                                 double weight, double gap2) {
  const NearestFeature f = nearest_feature(p, a, b, c);
  const std::array<double, 3> w = nearest_weights(f, p, a, b, c);
  const Vec3 r = p - (w[0] * a + w[1] * b + w[2] * c);
  const BarrierValue bv = contact_barrier(r.squaredNorm(), gap2);
  if (bv.first == 0.0) return ContactGradient::Zero();
  ContactGradient g;
  g.segment<3>(0) = 2.0 * r;
  for (int k = 0; k < 3; ++k) g.segment<3>(3 + 3 * k) = -2.0 * w[static_cast<size_t>(k)] * r;
  return weight * bv.first * g;
}

ContactHessian contact_hessian(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                               double weight, double gap2, bool project) {
  const NearestFeature f = nearest_feature(p, a, b, c);
  const auto x = as_arrays(p, a, b, c);
  if (!(feature_d2<double>(f, x) < gap2)) return ContactHessian::Zero();
  const SecondOrder s = second_order(f, x);
  const BarrierValue bv = contact_barrier(s.d2, gap2);
  const ContactHessian h =
      weight * (bv.second * s.gradient * s.gradient.transpose() + bv.first * s.hessian);
  return project ? project_psd(h) : h;
}

}  // namespace membra
