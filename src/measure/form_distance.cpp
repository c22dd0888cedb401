#include "membra/measure/form_distance.hpp"

#include <Eigen/SVD>
#include <stdexcept>

namespace membra {

double form_distance(const Points& a, const Points& b, bool align) {
  if (a.cols() != b.cols() || a.cols() == 0)
    throw std::invalid_argument("form_distance: the forms have different particle counts");
  const double n = static_cast<double>(a.cols());
  if (!align) return std::sqrt((a - b).colwise().squaredNorm().sum() / n);
  const Vec3 ca = a.rowwise().mean(), cb = b.rowwise().mean();
  const Points pa = a.colwise() - ca, pb = b.colwise() - cb;
  // Kabsch: R = V diag(1, 1, det) U^T from the SVD of the covariance, without reflections.
  const Eigen::Matrix3d cov = pa * pb.transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(cov, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  const Eigen::Matrix3d r = svd.matrixV() * d * svd.matrixU().transpose();
  return std::sqrt(((r * pa) - pb).colwise().squaredNorm().sum() / n);
}

}  // namespace membra
