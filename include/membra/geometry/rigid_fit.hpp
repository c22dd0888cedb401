#pragma once
// The best rigid motion (rotation and translation, no mirror) between two corresponding point
// sets in the least-squares sense: Kabsch's rotation from the SVD of their cross-covariance
// (W. Kabsch 1976, "A solution for the best rotation to relate two sets of vectors", Acta
// Cryst. A32, 922-923). One copy serves every distance between forms (measure, design).
#include <Eigen/Core>
#include <Eigen/SVD>

#include "membra/core/vec.hpp"

namespace membra {

// x -> R x + t.
struct RigidMotion {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Vec3 translation = Vec3::Zero();
  Vec3 apply(const Vec3& p) const { return rotation * p + translation; }
};

// The proper rotation R (det R = +1) minimising sum_i w_i |R (p_i - p0) - (q_i - q0)|^2, from
// the cross-covariance h = sum_i w_i (p_i - p0)(q_i - q0)^T of the centred sets: with
// h = U S V^T, R = V diag(1, 1, d) U^T, d = sign det(V U^T) (d = -1 would be a mirror).
inline Eigen::Matrix3d kabsch_rotation(const Eigen::Matrix3d& h) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  // Assigned, not constructed: Eigen evaluates the product differently in the two, and the
  // designs' numbers were measured with the assignment.
  Eigen::Matrix3d r;
  r = svd.matrixV() * d * svd.matrixU().transpose();
  return r;
}

// The rigid motion taking the columns of p onto those of q (same count, at least one; weights
// w >= 0 with a positive sum, or empty for equal weights): R from kabsch_rotation, t matching
// the weighted centroids.
RigidMotion rigid_fit(const Points& p, const Points& q, const Eigen::VectorXd& w = {});

}  // namespace membra
