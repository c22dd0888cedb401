#include "membra/solve/rigid_gauge.hpp"

namespace membra {
namespace {

// Ties (a symmetric sheet has several particles equally near the centre or far from it) go to
// the lowest index: a choice within round-off of another would flip with the last digits of the
// form, and with it the held coordinates (and a cached Newton setup, which fits only its own).
// `tie` is the squared distance below which two candidates count as equal.
bool better(double d, double best, double tie, bool larger) {
  return larger ? d > best + tie : d < best - tie;
}

// a, the particle nearest the centre, and b, the one farthest from a, of positions y.
std::pair<int, int> centre_and_far(const Points& y, double tie) {
  const Vec3 centre = y.rowwise().mean();
  int a = 0, b = 0;
  double best_a = 1e300, best_b = -1.0;
  for (Eigen::Index p = 0; p < y.cols(); ++p) {
    const double d = (y.col(p) - centre).squaredNorm();
    if (better(d, best_a, tie, false)) best_a = d, a = static_cast<int>(p);
  }
  for (Eigen::Index p = 0; p < y.cols(); ++p) {
    const double d = (y.col(p) - y.col(a)).squaredNorm();
    if (better(d, best_b, tie, true)) best_b = d, b = static_cast<int>(p);
  }
  return {a, b};
}

// Squared distances closer than 1e-4 of the sheet's squared extent are ties: a particle that
// near the centre, or that near the farthest, holds the gauge as well (a Newton step moves a
// symmetric sheet's corners apart by far more than round-off).
double tie_of(const Points& x) {
  return 1e-4 * (x.rowwise().maxCoeff() - x.rowwise().minCoeff()).squaredNorm();
}

}  // namespace

RigidGauge rigid_gauge(const Points& x) {
  const double tie = tie_of(x);
  const auto [a, b] = centre_and_far(x, tie);
  int c = 0;
  double best_c = -1.0;
  const Vec3 e1 = (x.col(b) - x.col(a)).normalized();
  for (Eigen::Index p = 0; p < x.cols(); ++p) {
    const double d = (x.col(p) - x.col(a)).cross(e1).squaredNorm();
    if (better(d, best_c, tie, true)) best_c = d, c = static_cast<int>(p);
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
  const auto [a, b] = centre_and_far(flat, tie_of(flat));
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
