#include "membra/geometry/rigid_fit.hpp"

#include <stdexcept>

namespace membra {

RigidMotion rigid_fit(const Points& p, const Points& q, const Eigen::VectorXd& w) {
  if (p.cols() != q.cols() || p.cols() == 0 || (w.size() != 0 && w.size() != p.cols()))
    throw std::invalid_argument(
        "rigid_fit: the point sets (and weights) differ in size or are empty");
  const Eigen::VectorXd weight = w.size() == 0 ? Eigen::VectorXd::Ones(p.cols()).eval() : w;
  const double total = weight.sum();
  if (!(total > 0.0)) throw std::invalid_argument("rigid_fit: the weights sum to zero");
  const Vec3 cp = p * weight / total, cq = q * weight / total;
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  for (Eigen::Index i = 0; i < p.cols(); ++i)
    h += weight[i] * (p.col(i) - cp) * (q.col(i) - cq).transpose();
  RigidMotion m;
  m.rotation = kabsch_rotation(h);
  m.translation = cq - m.rotation * cp;
  return m;
}

}  // namespace membra
