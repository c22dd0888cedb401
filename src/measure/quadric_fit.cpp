#include "membra/measure/quadric_fit.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Dense>

namespace membra {
namespace {

using Basis = Eigen::Matrix<double, 6, 1>;

// 1, u, v, u^2, uv, v^2 at paper offset (u, v), scaled to about [-1, 1] for conditioning.
Basis basis(double u, double v) {
  Basis b;
  b << 1.0, u, v, u * u, u * v, v * v;
  return b;
}

// Normal of the fitted surface c (6 x 3 coefficients, row i the coefficient of basis i) at (u, v).
Vec3 normal_at(const Eigen::Matrix<double, 6, 3>& c, double u, double v) {
  const Vec3 xu = (c.row(1) + 2.0 * u * c.row(3) + v * c.row(4)).transpose();
  const Vec3 xv = (c.row(2) + u * c.row(4) + 2.0 * v * c.row(5)).transpose();
  const Vec3 n = xu.cross(xv);
  return n.norm() > 0.0 ? Vec3(n / n.norm()) : Vec3::Zero();  // a folded fit: no normal there
}

}  // namespace

std::string classify_quadric(double k1, double k2, double size) {
  const double larger = std::max(std::abs(k1), std::abs(k2));
  const double smaller = std::min(std::abs(k1), std::abs(k2));
  if (!(larger * size >= 0.05)) return "flat";
  if (smaller < 0.25 * larger) return "cylindrical";
  return k1 * k2 > 0.0 ? "synclastic" : "anticlastic";
}

QuadricFit fit_quadric(const Points& x, const Points& paper) {
  QuadricFit q;
  const Eigen::Index n = x.cols();
  if (n < 6 || paper.cols() != n) return q;
  const Vec2 centre = paper.topRows<2>().rowwise().mean();
  const Vec2 lo = paper.topRows<2>().rowwise().minCoeff();
  const Vec2 hi = paper.topRows<2>().rowwise().maxCoeff();
  const double scale = 0.5 * std::max(hi.x() - lo.x(), hi.y() - lo.y());
  if (!(scale > 0.0)) return q;
  // Normal equations of the 6-term fit, all three coordinates at once.
  Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 3> b = Eigen::Matrix<double, 6, 3>::Zero();
  for (Eigen::Index p = 0; p < n; ++p) {
    const Vec2 uv = (paper.col(p).head<2>() - centre) / scale;
    const Basis f = basis(uv.x(), uv.y());
    a.noalias() += f * f.transpose();
    b.noalias() += f * x.col(p).transpose();
  }
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(a);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 1e-12 * a.trace())) return q;
  const Eigen::Matrix<double, 6, 3> c = ldlt.solve(b);
  // First and second fundamental forms at the centre (u = v = 0).
  const Vec3 xu = c.row(1).transpose(), xv = c.row(2).transpose();
  const Vec3 xuu = 2.0 * c.row(3).transpose(), xuv = c.row(4).transpose();
  const Vec3 xvv = 2.0 * c.row(5).transpose();
  const Vec3 normal = normal_at(c, 0.0, 0.0);
  const Eigen::Matrix2d first{{xu.dot(xu), xu.dot(xv)}, {xu.dot(xv), xv.dot(xv)}};
  const Eigen::Matrix2d second{{xuu.dot(normal), xuv.dot(normal)},
                               {xuv.dot(normal), xvv.dot(normal)}};
  if (!(first.determinant() > 0.0) || normal.isZero()) return q;
  // Principal curvatures: eigenvalues of I^-1 II, via the symmetric form L^-1 II L^-T.
  const Eigen::Matrix2d l = first.llt().matrixL();
  const Eigen::Matrix2d shape = l.inverse() * second * l.inverse().transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(shape);
  double k1 = eig.eigenvalues()(1), k2 = eig.eigenvalues()(0);
  // Principal directions in space: an eigenvector w of the symmetric form is L^T a for the
  // parameter direction a.
  const auto direction = [&](int i) {
    const Eigen::Vector2d along =
        l.transpose().triangularView<Eigen::Upper>().solve(eig.eigenvectors().col(i));
    return Vec3((along.x() * xu + along.y() * xv).normalized());
  };
  Vec3 d1 = direction(1), d2 = direction(0), up = normal;
  if (k1 + k2 < 0.0) {  // the normal the other way: both curvatures change sign
    const double old_k1 = k1;
    k1 = -k2;
    k2 = -old_k1;
    std::swap(d1, d2);
    up = -normal;
  }
  q.k1 = k1;
  q.k2 = k2;
  q.centre = c.row(0).transpose();
  q.normal = up;
  q.d1 = d1;
  q.d2 = d2;
  q.paper_x = xu.normalized();
  double sum = 0.0;
  for (Eigen::Index p = 0; p < n; ++p) {
    const Vec2 uv = (paper.col(p).head<2>() - centre) / scale;
    const Vec3 fitted = c.transpose() * basis(uv.x(), uv.y());
    const double d = (x.col(p) - fitted).dot(normal_at(c, uv.x(), uv.y()));
    sum += d * d;
  }
  q.rms = std::sqrt(sum / static_cast<double>(n));
  // A sheet that rolls up or folds over turns more within its half-width than a quadric can (a
  // roll closes at k L = pi); its fit then shrinks to a sliver at the centre, and the curvatures
  // there are not the form's.
  const double half_width = std::pow(first.determinant(), 0.25);
  const bool described = std::max(std::abs(k1), std::abs(k2)) * half_width <= 2.0 &&
                         half_width >= std::sqrt(0.1) * scale;
  q.classification = described ? classify_quadric(k1, k2, scale) : "folded";
  q.valid = true;
  return q;
}

}  // namespace membra
