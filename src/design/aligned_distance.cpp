#include "membra/design/aligned_distance.hpp"

#include <Eigen/SVD>

namespace membra {

AlignedDistance aligned_distance(const Points& x, const Correspondence& c) {
  const Eigen::Index n = x.cols();
  // The optimal translation matches weighted centroids: with weights not summing to one it would
  // not, and the gradient (envelope theorem) would be wrong.
  const double total = c.weight.sum();
  const Vec3 xm = x * c.weight / total, tm = c.target * c.weight / total;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (Eigen::Index i = 0; i < n; ++i)
    cov += c.weight[i] * (c.target.col(i) - tm) * (x.col(i) - xm).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(cov, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0) d(2, 2) = -1.0;
  AlignedDistance a;
  a.motion.rotation = svd.matrixU() * d * svd.matrixV().transpose();
  a.motion.translation = tm - a.motion.rotation * xm;
  a.gradient.resize(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Vec3 r = a.motion.apply(x.col(i)) - c.target.col(i);
    a.value += c.weight[i] * r.squaredNorm();
    a.gradient.col(i) = 2.0 * c.weight[i] * (a.motion.rotation.transpose() * r);
  }
  return a;
}

}  // namespace membra
