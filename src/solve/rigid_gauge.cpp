#include "membra/solve/rigid_gauge.hpp"

namespace membra {

RigidGauge rigid_gauge(const Points& x) {
  const Vec3 centre = x.rowwise().mean();
  int a = 0, b = 0, c = 0;
  double best_a = 1e300, best_b = -1.0, best_c = -1.0;
  for (Eigen::Index p = 0; p < x.cols(); ++p) {
    const double d = (x.col(p) - centre).squaredNorm();
    if (d < best_a) best_a = d, a = static_cast<int>(p);
  }
  for (Eigen::Index p = 0; p < x.cols(); ++p) {
    const double d = (x.col(p) - x.col(a)).squaredNorm();
    if (d > best_b) best_b = d, b = static_cast<int>(p);
  }
  const Vec3 e1 = (x.col(b) - x.col(a)).normalized();
  for (Eigen::Index p = 0; p < x.cols(); ++p) {
    const double d = (x.col(p) - x.col(a)).cross(e1).squaredNorm();
    if (d > best_c) best_c = d, c = static_cast<int>(p);
  }
  RigidGauge g;
  const Vec3 e3 = e1.cross(x.col(c) - x.col(a)).normalized();
  if (e1.allFinite() && e3.allFinite()) {
    g.rotation.row(0) = e1.transpose();
    g.rotation.row(1) = e3.cross(e1).transpose();
    g.rotation.row(2) = e3.transpose();
  }
  g.held = {3 * a, 3 * a + 1, 3 * a + 2, 3 * b + 1, 3 * b + 2, 3 * c + 2};
  return g;
}

}  // namespace membra
