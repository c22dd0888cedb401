#pragma once
// Second-order forward differentiation: a value with its gradient and Hessian over N inputs, for
// exact element Hessians of short geometric formulas. Eigen's nested AutoDiffScalar does the same
// but carries N inner duals per entry and no fixed-size vectorization: on the shell triangles'
// curvature scalars this dense form is several times faster (docs/performance.md).
#include <cmath>

#include <Eigen/Core>

namespace membra {

template <int N>
struct SecondOrder {
  using Gradient = Eigen::Matrix<double, N, 1>;
  using Hessian = Eigen::Matrix<double, N, N>;
  double v = 0.0;
  Gradient g = Gradient::Zero();
  Hessian h = Hessian::Zero();

  SecondOrder() = default;
  SecondOrder(double value) : v(value) {}  // NOLINT: constants mix with variables implicitly
  // Input i of N, at `value`.
  static SecondOrder variable(double value, int i) {
    SecondOrder out(value);
    out.g[i] = 1.0;
    return out;
  }
};

template <int N>
SecondOrder<N> operator+(SecondOrder<N> a, const SecondOrder<N>& b) {
  a.v += b.v;
  a.g += b.g;
  a.h += b.h;
  return a;
}

template <int N>
SecondOrder<N> operator-(SecondOrder<N> a, const SecondOrder<N>& b) {
  a.v -= b.v;
  a.g -= b.g;
  a.h -= b.h;
  return a;
}

template <int N>
SecondOrder<N> operator-(SecondOrder<N> a) {
  a.v = -a.v;
  a.g = -a.g;
  a.h = -a.h;
  return a;
}

template <int N>
SecondOrder<N> operator*(const SecondOrder<N>& a, const SecondOrder<N>& b) {
  SecondOrder<N> out;
  out.v = a.v * b.v;
  out.g = a.v * b.g + b.v * a.g;
  const typename SecondOrder<N>::Hessian cross = a.g * b.g.transpose();
  out.h = a.v * b.h + b.v * a.h + cross + cross.transpose();
  return out;
}

template <int N>
SecondOrder<N> operator*(SecondOrder<N> a, double s) {
  a.v *= s;
  a.g *= s;
  a.h *= s;
  return a;
}

// f(a) by the chain rule, given f, f' and f'' at a's value.
template <int N>
SecondOrder<N> chain(const SecondOrder<N>& a, double f, double f1, double f2) {
  SecondOrder<N> out;
  out.v = f;
  out.g = f1 * a.g;
  out.h = f1 * a.h + f2 * a.g * a.g.transpose();
  return out;
}

template <int N>
SecondOrder<N> sqrt(const SecondOrder<N>& a) {
  const double r = std::sqrt(a.v);
  return chain(a, r, 0.5 / r, -0.25 / (r * a.v));
}

template <int N>
SecondOrder<N> operator/(const SecondOrder<N>& a, const SecondOrder<N>& b) {
  const double inv = 1.0 / b.v;
  return a * chain(b, inv, -inv * inv, 2.0 * inv * inv * inv);
}

}  // namespace membra
