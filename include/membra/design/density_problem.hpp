#pragma once
// Inverse design's second stage as a function of the design variables: for cell densities rho
// (design/density_field.hpp), the released equilibrium of the sheet with resin by density
// (design/resin_density.hpp), the objective — the aligned distance to the target's points
// (design/aligned_distance.hpp) over the squared target size, plus a smoothness term — and its
// gradient by the adjoint of the equilibrium (design/adjoint_solve.hpp):
//   H w = dJ/dx,  dJ/drho = -w . d(grad E)/drho.
// Each equilibrium is warm-started from the last one (a Newton solve at the new densities); only
// when that fails is the release path followed again from the stretched sheet.
#include <functional>
#include <memory>
#include <optional>

#include "membra/design/aligned_distance.hpp"
#include "membra/design/density_field.hpp"
#include "membra/design/resin_density.hpp"
#include "membra/design/resin_map.hpp"
#include "membra/process/prepare.hpp"
#include "membra/process/scene.hpp"

namespace membra {

struct DensityEvaluation {
  double objective = 0.0;  // distance / scale^2 + smoothing term (dimensionless)
  double distance = 0.0;   // the aligned distance alone, m^2
  Eigen::VectorXd gradient;
  bool converged = false;  // a stable equilibrium was found (else the gradient is zero)
  bool restarted = false;  // the warm start failed and the release path was followed again
  long newton_iterations = 0;
};

class DensityProblem {
 public:
  // `scene`: stretch, impregnate (its pattern is ignored: the resin goes everywhere, by
  // density), release, solved with its equilibrium solver. Throws InputError as a run would.
  DensityProblem(Scene scene, DensityField field);
  // The same problem for other variables: `make_map` gets the membrane impregnated everywhere on
  // its frame and the particles' frame positions, and returns how the variables place the resin
  // (e.g. a stencil's piece sizes, design/piece_map.hpp). field() is then empty.
  using MapMaker =
      std::function<std::unique_ptr<ResinMap>(const Membrane& stretched, const Points& frame_x)>;
  DensityProblem(Scene scene, const MapMaker& make_map);
  DensityProblem(const DensityProblem&) = delete;
  DensityProblem& operator=(const DensityProblem&) = delete;

  // The particles on the frame before release (where correspondences start), and their weights
  // (mass shares: area on the paper).
  const Points& frame_positions() const { return frame_x_; }
  Eigen::VectorXd area_weights() const;
  const DensityField& field() const;  // the density map's cells (empty for other maps)

  // The target: the point each particle should reach, and the length that makes the objective
  // dimensionless (e.g. the target's diameter). `smoothing` weighs the map's regularisation
  // (densities: the mean squared difference between neighbouring cells).
  void set_target(Correspondence target, double scale, double smoothing);

  // The released equilibrium for `rho`; false when no stable one was found. Newton starts from
  // the anchor (the last equilibrium until anchor() is called).
  bool solve(const Eigen::VectorXd& rho);
  // The released equilibrium for `rho` found by Newton from positions `x` (e.g. the form a
  // stencil released into from flat) instead of the release path, and anchored there: the
  // branch that later solves follow. False when none was found there.
  bool solve_from(const Eigen::VectorXd& rho, const Points& x);
  // Makes the present equilibrium the start of every later solve. A sheet is multistable: warm
  // starts from wherever the last solve ended make the form depend on the order of evaluations,
  // and a line search that steps back would not find the form it left. Anchored at the best
  // design so far, the form is a function of the densities along the branch through it.
  void anchor();
  // From now on a failed warm start is a failed solve, not a release from the frame (which may
  // end on another branch): for refining the branch a solve_from found.
  void keep_to_branch() { on_branch_only_ = true; }
  const Points& positions() const { return p_.membrane.state.x; }
  const Membrane& membrane() const { return p_.membrane; }

  DensityEvaluation evaluate(const Eigen::VectorXd& rho);

 private:
  bool release_from_frame(const Eigen::VectorXd& rho);
  void check_variables(const Eigen::VectorXd& rho) const;
  Scene scene_;
  PreparedScene stretched_;  // stretched and impregnated everywhere, before release
  PreparedScene p_;          // released (the path's set() refers to this one)
  Points frame_x_;
  std::unique_ptr<ResinMap> map_;
  Correspondence target_;
  double scale_ = 1.0, smoothing_ = 0.0;
  bool released_ = false;
  bool on_branch_only_ = false;
  Points anchor_;  // where warm starts begin (empty: the last equilibrium)
  long iterations_ = 0;
  int restarts_ = 0;
};

}  // namespace membra
