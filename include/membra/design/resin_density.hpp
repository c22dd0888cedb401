#pragma once
// Resin given by a density field instead of a stencil: every element the design places resin on
// takes the density at its site as its resin fraction (a spring's midpoint, a bending element's
// middle particle: ResinFootprint, model/elements/element_set.hpp), and
// the composite rules of the process (model/membrane.hpp) turn fractions into stiffness and rest
// length. The membrane must have been impregnated everywhere first (so each element knows its
// resin's stiffness and length at impregnation); the density then only sets the fractions.
// Both rules are smooth in the fraction, so the released form is smooth in the density and its
// gradient follows by the adjoint method (design/density_problem.hpp, design/adjoint_solve.hpp).
#include <vector>

#include <Eigen/Core>

#include "membra/design/density_field.hpp"
#include "membra/design/resin_map.hpp"
#include "membra/model/membrane.hpp"

namespace membra {

// Where each element reads the density: bilinear weights of the cells around its site on the
// frame (positions `x_frame`, the sheet stretched on its frame), per element set; `takes` false
// for an element the design places no resin on.
struct DensitySites {
  struct Site {
    DensityField::Weights weights;
    bool takes = false;
  };
  std::vector<std::vector<Site>> set;
  int cells = 0;
};
DensitySites density_sites(const Membrane& m, const Points& x_frame, const DensityField& field);

// Sets every element's resin fraction from the cell densities `rho` and
// updates their stiffness and rest length (at the membrane's present release level).
void apply_density(Membrane& m, const DensitySites& sites, const Eigen::VectorXd& rho);

// For each cell c, d/d rho_c of (grad E(x) . w): how the forces' virtual work along the
// displacement field w changes with the cell's density, at positions x. With w the adjoint
// solution this is the equilibrium's sensitivity term of the adjoint method.
Eigen::VectorXd density_force_sensitivity(const Membrane& m, const DensitySites& sites,
                                          const Points& x, const Points& w);

// The density field as a design's resin map: one variable per cell, regularised by the mean
// squared difference of neighbouring cells.
class DensityMap final : public ResinMap {
 public:
  DensityMap(DensityField field, DensitySites sites);
  Eigen::Index size() const override { return field_.value.size(); }
  void apply(Membrane& m, const Eigen::VectorXd& rho) const override;
  Eigen::VectorXd pull_back(const Membrane& m, const Eigen::VectorXd& rho, const Points& x,
                            const Points& w) const override;
  double regularization(const Eigen::VectorXd& rho, double weight,
                        Eigen::VectorXd* gradient) const override;
  const DensityField& field() const { return field_; }

 private:
  DensityField field_;
  DensitySites sites_;
};

}  // namespace membra
