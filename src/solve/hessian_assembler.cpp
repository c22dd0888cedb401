#include "membra/solve/hessian_assembler.hpp"

#include <algorithm>
#include <type_traits>

namespace membra {
namespace {

// Calls emit(row, col) for every pair of coordinates of the particles ps, in the order an
// element's Hessian block is stored (row-major over 3 x size(ps) coordinates).
template <typename Ids, typename Emit>
void visit_pairs(const Ids& ps, const std::vector<int>& dof, Emit&& emit) {
  const size_t n = 3 * ps.size();
  for (size_t r = 0; r < n; ++r)
    for (size_t c = 0; c < n; ++c)
      emit(dof[3 * static_cast<size_t>(ps[r / 3]) + r % 3],
           dof[3 * static_cast<size_t>(ps[c / 3]) + c % 3]);
}

}  // namespace

HessianAssembler::HessianAssembler(const Model& model, const std::vector<int>& dof, int ndof)
    : model_(&model) {
  // The pattern: every pair of free coordinates that share an element, lower triangle. Sized up
  // front: growing vectors of millions of entries cost more than filling them. The pattern keeps
  // an element's lower triangle (3n (3n + 1) / 2 of its (3n)^2 entries).
  size_t lower = 0;
  model.for_each_set([&](const auto& set) {
    constexpr size_t n = 3 * static_cast<size_t>(std::decay_t<decltype(set)>::kArity);
    lower += n * (n + 1) / 2 * static_cast<size_t>(set.size());
    slots_.emplace_back().reserve(n * n * static_cast<size_t>(set.size()));
  });
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(lower + static_cast<size_t>(ndof));
  diag_slots_.reserve(static_cast<size_t>(ndof));
  auto keep = [&](int r, int c) {
    if (r >= 0 && c >= 0 && r >= c) t.emplace_back(r, c, 0.0);
  };
  model.for_each_set([&](const auto& set) {
    for (int e = 0; e < set.size(); ++e) visit_pairs(set.ids(e), dof, keep);
  });
  for (int k = 0; k < ndof; ++k) t.emplace_back(k, k, 0.0);  // the diagonal, for shifts
  h_.resize(ndof, ndof);
  h_.setFromTriplets(t.begin(), t.end());
  h_.makeCompressed();
  // Each element's slots: where its entries go in the value array (-1: held or upper).
  auto slot_of = [&](std::vector<int>& slots) {
    return [&](int r, int c) {
      if (r < 0 || c < 0 || r < c) return slots.push_back(-1);
      const int* begin = h_.innerIndexPtr() + h_.outerIndexPtr()[c];
      const int* end = h_.innerIndexPtr() + h_.outerIndexPtr()[c + 1];
      slots.push_back(static_cast<int>(std::lower_bound(begin, end, r) - h_.innerIndexPtr()));
    };
  };
  size_t k = 0;
  model.for_each_set([&](const auto& set) {
    std::vector<int>& slots = slots_[k++];
    for (int e = 0; e < set.size(); ++e) visit_pairs(set.ids(e), dof, slot_of(slots));
  });
  for (int d = 0; d < ndof; ++d) slot_of(diag_slots_)(d, d);
}

template <int N>
void HessianAssembler::add_block(const Eigen::Matrix<double, 3 * N, 3 * N>& block,
                                 const int* slot) {
  double* val = h_.valuePtr();
  for (int r = 0; r < 3 * N; ++r)
    for (int c = 0; c < 3 * N; ++c, ++slot)
      if (*slot >= 0) val[*slot] += block(r, c);
}

// The elements' blocks are computed on all threads, a batch at a time, into a buffer, then added
// in element order on one thread: the matrix is the same bit for bit whatever the number of
// threads, and the buffer stays small.
const Eigen::SparseMatrix<double>& HessianAssembler::assemble(const Points& x, bool project) {
  std::fill(h_.valuePtr(), h_.valuePtr() + h_.nonZeros(), 0.0);
  constexpr int kBatch = 1024;
  size_t k = 0;
  model_->for_each_set([&](const auto& set) {
    constexpr int n = std::decay_t<decltype(set)>::kArity;
    using Block = Eigen::Matrix<double, 3 * n, 3 * n>;
    const std::vector<int>& slots = slots_[k++];
    std::vector<Block> blocks(static_cast<size_t>(std::min(set.size(), kBatch)));
    for (int first = 0; first < set.size(); first += kBatch) {
      const int count = std::min(kBatch, set.size() - first);
#pragma omp parallel for schedule(dynamic, 16) if (count * n * n >= 4096)
      for (int j = 0; j < count; ++j)
        if (set.active(first + j))
          blocks[static_cast<size_t>(j)] = set.hessian(first + j, x, project);
      for (int j = 0; j < count; ++j) {
        const int e = first + j;
        if (set.active(e))
          add_block<n>(blocks[static_cast<size_t>(j)], &slots[static_cast<size_t>(e) * 9 * n * n]);
      }
    }
  });
  return h_;
}

const Eigen::SparseMatrix<double>& HessianAssembler::add_to_diagonal(const Eigen::VectorXd& shift) {
  for (size_t k = 0; k < diag_slots_.size(); ++k)
    h_.valuePtr()[diag_slots_[k]] += shift[static_cast<Eigen::Index>(k)];
  return h_;
}

Eigen::VectorXd HessianAssembler::diagonal() const {
  Eigen::VectorXd d(static_cast<Eigen::Index>(diag_slots_.size()));
  for (size_t k = 0; k < diag_slots_.size(); ++k)
    d[static_cast<Eigen::Index>(k)] = h_.valuePtr()[diag_slots_[k]];
  return d;
}

Eigen::VectorXd HessianAssembler::multiply(const Eigen::VectorXd& v) const {
  return h_.selfadjointView<Eigen::Lower>() * v;
}

Eigen::SparseMatrix<double> potential_hessian(const Model& model, const Points& x) {
  std::vector<int> dof(static_cast<size_t>(x.size()));
  for (size_t k = 0; k < dof.size(); ++k) dof[k] = static_cast<int>(k);
  HessianAssembler assembler(model, dof, static_cast<int>(dof.size()));
  Eigen::SparseMatrix<double> full = assembler.assemble(x, false).selfadjointView<Eigen::Lower>();
  return full;
}

}  // namespace membra
