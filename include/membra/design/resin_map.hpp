#pragma once
// How a design's variables place the resin: they set the resin fraction of every element the
// design places resin on (each element set says which, where it lies, and how its fraction acts:
// model/elements/), and the chain rule takes the adjoint's per-element sensitivities back to the
// variables. Two maps exist: a density per cell (design/resin_density.hpp, stage 2) and the sizes
// of a stencil's pieces (design/piece_map.hpp, stage 3). The density problem
// (design/density_problem.hpp) solves and differentiates the released equilibrium for either.
// Both set fractions and take sensitivities per element by the functions below.
#include <vector>

#include <Eigen/Core>

#include "membra/model/membrane.hpp"

namespace membra {

// For every element of every set (in Model::for_each_set order), d/df of (grad E(x) . w) in its
// resin fraction f: what any design variable's sensitivity is made of (0 where the design places
// no resin).
struct ElementRates {
  std::vector<Eigen::VectorXd> set;
};
ElementRates element_force_sensitivity(const Membrane& m, const Points& x, const Points& w);

class ResinMap {
 public:
  virtual ~ResinMap() = default;
  virtual Eigen::Index size() const = 0;  // design variables
  // Sets the resin fractions of the impregnated-everywhere membrane `m` for variables `p` (and
  // the stiffness and rest length that follow, at its present release level).
  virtual void apply(Membrane& m, const Eigen::VectorXd& p) const = 0;
  // d/dp of (grad E(x) . w) at variables p: with w the adjoint solution, minus the objective's
  // gradient through the equilibrium.
  virtual Eigen::VectorXd pull_back(const Membrane& m, const Eigen::VectorXd& p, const Points& x,
                                    const Points& w) const = 0;
  // A regularising term added to the objective with `weight`, and its gradient (none: 0).
  virtual double regularization(const Eigen::VectorXd& p, double /*weight*/,
                                Eigen::VectorXd* gradient) const {
    *gradient = Eigen::VectorXd::Zero(p.size());
    return 0.0;
  }
};

}  // namespace membra
