#include "membra/measure/shape.hpp"

#include <Eigen/Eigenvalues>

namespace membra {

ShapeSummary summarize_shape(const Points& x) {
  ShapeSummary s;
  if (x.cols() == 0) return s;
  s.bbox_min = x.rowwise().minCoeff();
  s.bbox_max = x.rowwise().maxCoeff();
  s.z_range = s.bbox_max.z() - s.bbox_min.z();
  const Vec3 centroid = x.rowwise().mean();
  const Points centred = x.colwise() - centroid;
  const Eigen::Matrix3d cov = centred * centred.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  s.normal = eig.eigenvectors().col(0);  // eigenvalues ascend: column 0 is the plane normal
  if (s.normal.z() < 0) s.normal = -s.normal;
  const Eigen::RowVectorXd h = s.normal.transpose() * centred;
  s.height = h.maxCoeff() - h.minCoeff();
  return s;
}

}  // namespace membra
