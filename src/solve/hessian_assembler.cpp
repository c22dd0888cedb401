#include "membra/solve/hessian_assembler.hpp"

#include <algorithm>
#include <type_traits>

namespace membra {
namespace {

// Calls emit(k, row, col) for each entry k of an element's Hessian block in its lower triangle
// (k = r * 3n + c, c <= r; the block is symmetric), with the free coordinates row and col of its
// particles ps.
template <typename Ids, typename Emit>
void visit_lower(const Ids& ps, const std::vector<int>& dof, Emit&& emit) {
  const size_t n = 3 * ps.size();
  for (size_t r = 0; r < n; ++r)
    for (size_t c = 0; c <= r; ++c)
      emit(static_cast<int>(r * n + c), dof[3 * static_cast<size_t>(ps[r / 3]) + r % 3],
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
  });
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(lower + static_cast<size_t>(ndof));
  diag_slots_.reserve(static_cast<size_t>(ndof));
  model.for_each_set([&](const auto& set) {
    for (int e = 0; e < set.size(); ++e)
      visit_lower(set.ids(e), dof, [&](int, int r, int c) {
        if (r >= 0 && c >= 0) t.emplace_back(std::max(r, c), std::min(r, c), 0.0);
      });
  });
  for (int k = 0; k < ndof; ++k) t.emplace_back(k, k, 0.0);  // the diagonal, for shifts
  h_.resize(ndof, ndof);
  h_.setFromTriplets(t.begin(), t.end());
  h_.makeCompressed();
  auto slot = [&](int r, int c) {  // where (r, c), r >= c, is in the value array
    const int* begin = h_.innerIndexPtr() + h_.outerIndexPtr()[c];
    const int* end = h_.innerIndexPtr() + h_.outerIndexPtr()[c + 1];
    return static_cast<int>(std::lower_bound(begin, end, r) - h_.innerIndexPtr());
  };
  // Each element's entries: its block's lower triangle, held coordinates left out. An entry
  // off the block's diagonal stands for itself and its mirror; where both land on one matrix
  // entry (a particle twice in the stencil, on the matrix's diagonal) it is listed twice.
  model.for_each_set([&](const auto& set) {
    Entries& en = entries_.emplace_back();
    en.start.reserve(static_cast<size_t>(set.size()) + 1);
    for (int e = 0; e < set.size(); ++e) {
      en.start.push_back(en.entries.size());
      visit_lower(set.ids(e), dof, [&](int k, int r, int c) {
        if (r < 0 || c < 0) return;
        const int s = slot(std::max(r, c), std::min(r, c));
        en.entries.emplace_back(k, s);
        const int n3 = 3 * std::decay_t<decltype(set)>::kArity;
        if (r == c && k / n3 != k % n3) en.entries.emplace_back(k, s);
      });
    }
    en.start.push_back(en.entries.size());
  });
  for (int d = 0; d < ndof; ++d) diag_slots_.push_back(slot(d, d));
}

void HessianAssembler::add_block(const double* block, const std::pair<int, int>* begin,
                                 const std::pair<int, int>* end) {
  // Row-major entry numbers into Eigen's column-major block: the block is symmetric.
  double* val = h_.valuePtr();
  for (const auto* e = begin; e != end; ++e) val[e->second] += block[e->first];
}

// The elements' blocks are computed on all threads, a batch at a time, into a buffer, then added
// in element order on one thread: the matrix is the same bit for bit whatever the number of
// threads, and the buffer stays small (and is kept: a fresh one of megabytes costs page faults
// at every assembly).
const Eigen::SparseMatrix<double>& HessianAssembler::assemble(const Points& x, bool project) {
  std::fill(h_.valuePtr(), h_.valuePtr() + h_.nonZeros(), 0.0);
  shifted_ = false;
  constexpr int kBatch = 1024;
  size_t k = 0;
  model_->for_each_set([&](const auto& set) {
    constexpr int n = std::decay_t<decltype(set)>::kArity;
    constexpr size_t kSize = 9 * n * n;
    using Block = Eigen::Matrix<double, 3 * n, 3 * n>;
    const Entries& en = entries_[k++];
    const size_t need = kSize * static_cast<size_t>(std::min(set.size(), kBatch));
    if (buffer_.size() < need) buffer_.resize(need);
    for (int first = 0; first < set.size(); first += kBatch) {
      const int count = std::min(kBatch, set.size() - first);
#pragma omp parallel for schedule(dynamic, 16) if (count * n * n >= 4096)
      for (int j = 0; j < count; ++j)
        if (set.active(first + j))
          Eigen::Map<Block>(buffer_.data() + kSize * static_cast<size_t>(j)) =
              set.hessian(first + j, x, project);
      for (int j = 0; j < count; ++j) {
        const int e = first + j;
        if (set.active(e))
          add_block(buffer_.data() + kSize * static_cast<size_t>(j),
                    en.entries.data() + en.start[static_cast<size_t>(e)],
                    en.entries.data() + en.start[static_cast<size_t>(e) + 1]);
      }
    }
  });
  return h_;
}

const Eigen::SparseMatrix<double>& HessianAssembler::add_to_diagonal(const Eigen::VectorXd& shift) {
  if (!shifted_) unshifted_diagonal_ = diagonal();
  shifted_ = true;
  for (size_t k = 0; k < diag_slots_.size(); ++k)
    h_.valuePtr()[diag_slots_[k]] += shift[static_cast<Eigen::Index>(k)];
  return h_;
}

const Eigen::SparseMatrix<double>& HessianAssembler::remove_shifts() {
  if (shifted_)
    for (size_t k = 0; k < diag_slots_.size(); ++k)
      h_.valuePtr()[diag_slots_[k]] = unshifted_diagonal_[static_cast<Eigen::Index>(k)];
  shifted_ = false;
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
