#pragma once
// Projection of a small symmetric matrix onto the positive semi-definite cone: the eigenvalues
// below zero are set to zero (the closest PSD matrix in the Frobenius norm). Newton uses it per
// element while the assembled Hessian is indefinite, so that every element only ever pulls the
// step towards lower energy (docs/solver.md).
#include <Eigen/Eigenvalues>

namespace membra {

template <int N>
Eigen::Matrix<double, N, N> project_psd(const Eigen::Matrix<double, N, N>& m) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> es(m);
  const auto& l = es.eigenvalues();
  if (l.minCoeff() >= 0.0) return m;
  const auto& v = es.eigenvectors();
  return v * l.cwiseMax(0.0).asDiagonal() * v.transpose();
}

}  // namespace membra
