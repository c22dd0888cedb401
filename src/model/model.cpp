#include "membra/model/model.hpp"

#include <cmath>
#include <stdexcept>

namespace membra {

int Model::add_particle(double m, const Vec3& x) {
  if (!(m > 0.0)) throw std::invalid_argument("particle mass must be positive");
  mass.push_back(m);
  inv_mass.push_back(1.0 / m);
  const auto n = reference.cols();
  reference.conservativeResize(3, n + 1);
  reference.col(n) = x;
  return static_cast<int>(n);
}

double saddle_escape_length(const Model& model) {
  double sum = 0.0;
  long count = 0;
  model.for_each_set([&](const auto& set) {
    if constexpr (requires { set.rest_length; }) {
      for (double l : set.rest_length) sum += l;
      count += static_cast<long>(set.rest_length.size());
    }
  });
  if (count > 0) return sum / static_cast<double>(count);
  if (model.reference.cols() < 2) return 1.0;
  const Vec3 extent = model.reference.rowwise().maxCoeff() - model.reference.rowwise().minCoeff();
  const double side = std::max(extent.x(), extent.y());
  return side > 0.0 ? side : 1.0;
}

State State::at_rest(const Model& model) {
  State s;
  s.x = model.reference;
  s.v = Points::Zero(3, model.num_particles());
  return s;
}

}  // namespace membra
