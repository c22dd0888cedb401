#pragma once
// Time integrators behind one interface. Each keeps its own scratch buffers so a step allocates
// nothing after the first.
#include <memory>
#include <string_view>
#include <vector>

#include "membra/model/model.hpp"

namespace membra {

class Integrator {
 public:
  virtual ~Integrator() = default;
  // Scene name of the method ("rk4", "symplectic_euler").
  virtual std::string_view name() const = 0;
  // Force evaluations one step costs.
  virtual int force_passes_per_step() const = 0;
  // Advances the state by dt seconds. Pinned particles (inverse mass 0) keep their position
  // and have zero velocity.
  virtual void step(const Model& model, State& state, double dt) = 0;
};

// The classical fourth-order Runge-Kutta method on (x, v): the paper's integrator.
std::unique_ptr<Integrator> make_rk4();
// Semi-implicit (symplectic) Euler: v += dt a(x, v); x += dt v. First order, bounded energy error.
std::unique_ptr<Integrator> make_symplectic_euler();
// By scene name; nullptr for an unknown name.
std::unique_ptr<Integrator> make_integrator(std::string_view name);
// Names accepted by make_integrator().
std::vector<std::string_view> integrator_names();

}  // namespace membra
