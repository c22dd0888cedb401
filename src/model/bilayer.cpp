#include "membra/model/bilayer.hpp"

#include <stdexcept>

#include <Eigen/Eigenvalues>

namespace membra {
double bilayer_curvature_per_strain(const Material& base, const Material& layer) {
  if (!(base.thickness > 0.0) || !(layer.thickness > 0.0) || !(base.youngs_modulus > 0.0) ||
      !(layer.youngs_modulus > 0.0))
    throw std::invalid_argument("bilayer: both materials need a positive thickness and modulus");
  const double m = layer.thickness / base.thickness;
  const double n = layer.youngs_modulus / base.youngs_modulus;
  const double t = 6.0 * (1.0 + m) * (1.0 + m) /
                   (3.0 * (1.0 + m) * (1.0 + m) + (1.0 + m * n) * (m * m + 1.0 / (m * n)));
  return t / (base.thickness + layer.thickness);
}

Eigen::Matrix2d in_plane_gradient(const Points& reference, const Points& x, int a, int b, int c) {
  Eigen::Matrix2d r, q;
  r << (reference.col(b) - reference.col(a)).head<2>(),
      (reference.col(c) - reference.col(a)).head<2>();
  q << (x.col(b) - x.col(a)).head<2>(), (x.col(c) - x.col(a)).head<2>();
  return q * r.inverse();
}

Eigen::Matrix2d misfit_strain(const Eigen::Matrix2d& f) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(f * f.transpose());
  const Eigen::Vector2d inv_stretch = eig.eigenvalues().cwiseMax(1e-12).cwiseSqrt().cwiseInverse();
  return Eigen::Matrix2d::Identity() -
         eig.eigenvectors() * inv_stretch.asDiagonal() * eig.eigenvectors().transpose();
}

}  // namespace membra
