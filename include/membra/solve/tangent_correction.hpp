#pragma once
// A second-order correction of Newton's step on a continuum sheet (docs/solver.md, "The tangent
// correction"). A step that bends a thin sheet also stretches it, by about half the square of its
// slope change, which the quadratic model at the step's start does not see: the trial point is
// stretched where the true path is not, the stiff membrane pays for it, and Newton creeps with
// short steps. The correction is one Newton step, at the trial point, on the particles' motion in
// the sheet's tangent planes alone, with the Hessian at the start restricted to them. That
// restricted matrix is the membrane's stiffness (no soft bending modes to amplify), so it takes
// back the stretch and leaves the bending to the next iteration. Continuum sheets only: the
// lattice has no triangles to give it tangent planes, and its steps stay as they were.
#include <memory>
#include <vector>

#include <Eigen/SparseCore>

#include "membra/geometry/triangulation.hpp"
#include "membra/model/model.hpp"

namespace membra {

class TangentCorrection {
 public:
  // dof, ndof: the solve's free coordinates (as HessianAssembler takes them).
  TangentCorrection(const Model& model, const std::vector<int>& dof, int ndof);
  ~TangentCorrection();

  // True when the model has membrane triangles to take tangent planes from.
  bool applies() const { return applies_; }

  // The correction e over the free coordinates for a step from x: minus the solve of the
  // Hessian at x (`lower`, its lower triangle) restricted to the tangent planes at x, applied to
  // the gradient `g_trial` at the step's end. False when the restricted matrix does not factor.
  bool correction(const Points& x, const Eigen::SparseMatrix<double>& lower,
                  const Eigen::VectorXd& g_trial, Eigen::VectorXd& e);

  // Work done so far, for the solve's report: factorizations and symbolic analyses (one per
  // solve: the restricted matrix's pattern is fixed while the sheet's elements are).
  long factorizations() const { return factorizations_; }
  long analyses() const { return analyses_; }
  // The Hessian's pattern changed (self-contact's pairs): analyse it again at the next solve.
  void forget_pattern();

 private:
  Eigen::SparseMatrix<double> basis(const Points& x) const;

  const std::vector<int>& dof_;
  int ndof_;
  bool applies_ = false;
  std::vector<int> movable_;         // particles with at least one free coordinate
  std::vector<Triangle> triangles_;  // the membrane triangles, for the normals
  struct Factor;                     // CHOLMOD's, seen only in the source
  std::unique_ptr<Factor> factor_;
  long factorizations_ = 0, analyses_ = 0;
};

}  // namespace membra
