#pragma once
// The Hessian of a model's potential energy over its free coordinates, assembled from the
// element sets' analytic Hessians (model/elements/) into a
// sparse matrix whose pattern is fixed at construction: each element knows the positions of its
// entries in the value array, so an assembly only adds numbers. Only the lower triangle is kept,
// as the sparse Cholesky factorization reads it (docs/solver.md).
#include <utility>
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
  // The last assembled matrix as it was assembled, bit for bit, its shifts taken off.
  const Eigen::SparseMatrix<double>& remove_shifts();
  // The diagonal of the last assembled matrix.
  Eigen::VectorXd diagonal() const;
  // The lower triangle (the matrix the factorization reads).
  const Eigen::SparseMatrix<double>& lower() const { return h_; }
  // y = H v with the full symmetric matrix.
  Eigen::VectorXd multiply(const Eigen::VectorXd& v) const;

 private:
  // An element set's entries: (entry of an element's block, its place in the value array),
  // element e's from start[e] to start[e + 1].
  struct Entries {
    std::vector<size_t> start;
    std::vector<std::pair<int, int>> entries;
  };
  // Adds an element's block (column-major) at its entries.
  void add_block(const double* block, const std::pair<int, int>* begin,
                 const std::pair<int, int>* end);

  const Model* model_;
  Eigen::SparseMatrix<double> h_;
  std::vector<Entries> entries_;  // per element set, in Model::for_each_set order
  std::vector<int> diag_slots_;
  bool shifted_ = false;  // add_to_diagonal since the assembly: its diagonal kept below
  Eigen::VectorXd unshifted_diagonal_;
  std::vector<double> buffer_;  // a batch of element blocks
};

// The Hessian of the potential energy at x over all 3N coordinates (pins ignored), full
// symmetric, N/m.
Eigen::SparseMatrix<double> potential_hessian(const Model& model, const Points& x);

}  // namespace membra
