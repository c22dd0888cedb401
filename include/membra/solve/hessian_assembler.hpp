#pragma once
// The Hessian of a model's potential energy over its free coordinates, assembled from the
// element sets' analytic Hessians (model/elements/) into a
// sparse matrix whose pattern is fixed at construction: each element knows the positions of its
// entries in the value array, so an assembly only adds numbers. Only the lower triangle is kept,
// as the sparse Cholesky factorization reads it (docs/solver.md).
#include <vector>

#include <Eigen/SparseCore>

#include "membra/model/model.hpp"

namespace membra {

class HessianAssembler {
 public:
  // dof[3 p + c] is the free coordinate number of coordinate c of particle p, or -1 when it is
  // held (pinned, or fixed by the gauge); ndof free coordinates in all.
  HessianAssembler(const Model& model, const std::vector<int>& dof, int ndof);
  // Reads `model` from now on: another model with the same elements (the pattern is kept).
  void bind(const Model& model) { model_ = &model; }

  // Assembles the Hessian at x (N/m): exact, or with `project` every element's Hessian replaced
  // by the closest positive semi-definite matrix (so the sum is positive semi-definite).
  const Eigen::SparseMatrix<double>& assemble(const Points& x, bool project);
  // Adds shift[k] to diagonal entry k of the last assembled matrix.
  const Eigen::SparseMatrix<double>& add_to_diagonal(const Eigen::VectorXd& shift);
  // The diagonal of the last assembled matrix.
  Eigen::VectorXd diagonal() const;
  // The lower triangle (the matrix the factorization reads).
  const Eigen::SparseMatrix<double>& lower() const { return h_; }
  // y = H v with the full symmetric matrix.
  Eigen::VectorXd multiply(const Eigen::VectorXd& v) const;

 private:
  template <int N>
  void add_block(const Eigen::Matrix<double, 3 * N, 3 * N>& block, const int* slot);

  const Model* model_;
  Eigen::SparseMatrix<double> h_;
  std::vector<std::vector<int>> slots_;  // per element set, in Model::for_each_set order
  std::vector<int> diag_slots_;
};

// The Hessian of the potential energy at x over all 3N coordinates (pins ignored), full
// symmetric, N/m.
Eigen::SparseMatrix<double> potential_hessian(const Model& model, const Points& x);

}  // namespace membra
