#include "membra/solve/rigid_gauge.hpp"

namespace membra {
namespace {

// a, the particle nearest the centre, and b, the one farthest from a, of positions y.
std::pair<int, int> centre_and_far(const Points& y) {
  const Vec3 centre = y.rowwise().mean();
  int a = 0, b = 0;
  double best_a = 1e300, best_b = -1.0;
  for (Eigen::Index p = 0; p < y.cols(); ++p) {
    const double d = (y.col(p) - centre).squaredNorm();
    if (d < best_a) best_a = d, a = static_cast<int>(p);
  }
  for (Eigen::Index p = 0; p < y.cols(); ++p) {
    const double d = (y.col(p) - y.col(a)).squaredNorm();
    if (d > best_b) best_b = d, b = static_cast<int>(p);
  }
  return {a, b};
}

}  // namespace

RigidGauge rigid_gauge(const Points& x) {
  const auto [a, b] = centre_and_far(x);
  int c = 0;
  double best_c = -1.0;
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

RigidGauge planar_gauge(const Points& x) {
  Points flat = x;
  flat.row(2).setZero();  // a and b chosen as seen from above
  const auto [a, b] = centre_and_far(flat);
  RigidGauge g;
  const Vec3 e1 = (flat.col(b) - flat.col(a)).normalized();
  if (e1.allFinite()) {
    g.rotation.row(0) = e1.transpose();
    g.rotation.row(1) = Vec3(-e1.y(), e1.x(), 0.0).transpose();
  }
  g.held = {3 * a, 3 * a + 1, 3 * b + 1};
  return g;
}

bool held_by_table(const Model& model) {
  return model.table.size() > 0 && model.gravity.z() < 0.0;
}

RigidGauge free_sheet_gauge(const Model& model, const Points& x) {
  return held_by_table(model) ? planar_gauge(x) : rigid_gauge(x);
}

}  // namespace membra
