#include "membra/solve/rigid_gauge.hpp"

#include <algorithm>
#include <cmath>

namespace membra {
namespace {

// The particle whose value(p) is the largest (or the smallest); ties go to the lowest index among
// those within 1e-4 of the best, relative. A symmetric sheet has several particles equally near
// its centre or far from it, and with a strict comparison the choice followed the last digits of
// the form: the held coordinates changed from one solve to the next (and a cached Newton setup,
// which fits only its own, was built again).
template <class Value>
int first_best(Eigen::Index n, Value value, bool largest) {
  double best = largest ? -1e300 : 1e300;
  for (Eigen::Index p = 0; p < n; ++p)
    best = largest ? std::max(best, value(p)) : std::min(best, value(p));
  const double slack = 1e-4 * std::abs(best);
  for (Eigen::Index p = 0; p < n; ++p)
    if (largest ? value(p) >= best - slack : value(p) <= best + slack) return static_cast<int>(p);
  return 0;
}

// a, the particle nearest the centre, and b, the one farthest from a, of positions y.
std::pair<int, int> centre_and_far(const Points& y) {
  const Vec3 centre = y.rowwise().mean();
  const int a = first_best(
      y.cols(), [&](Eigen::Index p) { return (y.col(p) - centre).squaredNorm(); }, false);
  const int b = first_best(
      y.cols(), [&](Eigen::Index p) { return (y.col(p) - y.col(a)).squaredNorm(); }, true);
  return {a, b};
}

}  // namespace

RigidGauge rigid_gauge(const Points& x) {
  // Not a structured binding: clang 14 (the sanitized build's) cannot capture one in a lambda.
  const std::pair<int, int> ab = centre_and_far(x);
  const int a = ab.first, b = ab.second;
  const Vec3 e1 = (x.col(b) - x.col(a)).normalized();
  const int c = first_best(
      x.cols(), [&](Eigen::Index p) { return (x.col(p) - x.col(a)).cross(e1).squaredNorm(); },
      true);
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
