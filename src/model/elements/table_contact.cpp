#include "membra/model/elements/table_contact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace membra {

static_assert(ElementSet<TableContact>);

void TableContact::rest_on(const std::vector<double>& mass, double g, double h, double delta) {
  if (!(g > 0.0) || !std::isfinite(g))
    throw std::invalid_argument("a table holds the piece against gravity: G must be positive");
  if (!(delta > 0.0) || !std::isfinite(delta))
    throw std::invalid_argument("the table's softness must be positive");
  particle.clear();
  weight.clear();
  for (size_t p = 0; p < mass.size(); ++p) {
    particle.push_back(static_cast<int>(p));
    weight.push_back(mass[p] * g);
  }
  height = h;
  softness = delta;
  gravity = g;
}

void TableContact::cover(const std::vector<double>& mass) {
  if (!particle.empty()) rest_on(mass, gravity, height, softness);
}

void TableContact::filter(const std::vector<bool>& keep) {
  keep_where(particle, keep);
  keep_where(weight, keep);
}

double TableContact::depth(int i, const Points& x) const {
  return std::max(0.0, height - x(2, particle[static_cast<size_t>(i)]));
}

double TableContact::energy(int i, const Points& x) const {
  const double d = depth(i, x);
  return weight[static_cast<size_t>(i)] * d * d * d / (3.0 * softness * softness);
}

void TableContact::add_forces(const Points& x, const Points*, int begin, int end, Points& f) const {
  for (int i = begin; i < end; ++i) {
    const double d = depth(i, x);
    f(2, particle[static_cast<size_t>(i)]) +=
        weight[static_cast<size_t>(i)] * d * d / (softness * softness);
  }
}

Eigen::Matrix3d TableContact::hessian(int i, const Points& x, bool) const {
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  h(2, 2) = 2.0 * weight[static_cast<size_t>(i)] * depth(i, x) / (softness * softness);
  return h;  // positive semi-definite as it is
}

TableReading TableContact::read(const Points& x) const {
  TableReading r;
  for (int i = 0; i < size(); ++i) {
    const double d = depth(i, x), w = weight[static_cast<size_t>(i)];
    r.touching += d > 0.0;
    r.max_depth = std::max(r.max_depth, d);
    r.reaction += w * d * d / (softness * softness);
    r.weight += w;
  }
  return r;
}

void TableContact::add_stiffness_estimate(const Points&, std::vector<double>& diag) const {
  for (int i = 0; i < size(); ++i)
    diag[static_cast<size_t>(particle[static_cast<size_t>(i)])] +=
        2.0 * weight[static_cast<size_t>(i)] / softness;
}

void TableContact::carry(const TableContact& old, const Rebuild& r) {
  particle.clear();
  weight.clear();
  height = old.height;
  softness = old.softness;
  gravity = old.gravity;
  for (int i = 0; i < old.size(); ++i) {
    std::array<int, 1> ids{};
    if (!r.map(old.ids(i), ids)) continue;
    particle.push_back(ids[0]);
    weight.push_back(old.weight[static_cast<size_t>(i)]);
  }
}

}  // namespace membra
