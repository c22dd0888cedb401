#pragma once
// What a Newton solve sets up before its first factorization: the Hessians' sparsity pattern
// (exact and projected) and CHOLMOD's symbolic analysis (fill-reducing ordering, supernodes).
// At 128^2 it costs about as much as a factorization, and a path solves the same sheet increment
// after increment, so a NewtonCache keeps it for the next solve (docs/solver.md). A solve reuses
// it only when the model's elements and the free coordinates are exactly its own, so the
// factorizations, and the results, are those of a fresh setup, bit for bit.
#include <memory>
#include <mutex>
#include <vector>

#include <Eigen/CholmodSupport>

#include "membra/model/model.hpp"
#include "membra/solve/hessian_assembler.hpp"

namespace membra {

struct NewtonWorkspace {
  // dof, ndof: the free coordinates, as HessianAssembler takes them.
  NewtonWorkspace(const Model& model, const std::vector<int>& dof, int ndof);
  NewtonWorkspace(const NewtonWorkspace&) = delete;
  NewtonWorkspace& operator=(const NewtonWorkspace&) = delete;

  // True when `model` has the elements, and `dof` the free coordinates, this was set up for.
  bool fits(const Model& model, const std::vector<int>& dof) const;
  // The assemblers read `model` from now on (a model that fits).
  void bind(const Model& model);
  // Factorizes `a` (a matrix of the assemblers' pattern) into llt, on one thread
  // (SerialFactorization), analysing the pattern the first time; false where `a` is not
  // positive definite.
  bool factorize(const Eigen::SparseMatrix<double>& a);

  HessianAssembler exact, projected;
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>> llt;
  bool analysed = false;  // llt's symbolic analysis is done (on the pattern of `exact`)

 private:
  std::vector<int> dof_;
  std::vector<int> elements_;  // every element's particles, set by set
};

// A workspace kept between solves. A solve that finds the cache in use (another thread's solve of
// a copy of the scene) sets up its own instead of waiting.
struct NewtonCache {
  std::mutex in_use;
  std::unique_ptr<NewtonWorkspace> workspace;
};

}  // namespace membra
