#include "membra/model/model.hpp"

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

State State::at_rest(const Model& model) {
  State s;
  s.x = model.reference;
  s.v = Points::Zero(3, model.num_particles());
  return s;
}

}  // namespace membra
