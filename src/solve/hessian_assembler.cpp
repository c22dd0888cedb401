#include "membra/solve/hessian_assembler.hpp"

#include <algorithm>
#include <array>

#include "membra/model/bend_kernel.hpp"
#include "membra/model/hinge_kernel.hpp"
#include "membra/model/spring_kernel.hpp"

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

std::array<int, 2> spring_ends(const Springs& s, int i) {
  return {s.a[i], s.b[i]};
}

}  // namespace

HessianAssembler::HessianAssembler(const Model& model, const std::vector<int>& dof, int ndof)
    : model_(&model) {
  // The pattern: every pair of free coordinates that share an element, lower triangle.
  const Springs& s = model.springs;
  const Bending& b = model.bending;
  const Hinges& h = model.hinges;
  // Sized up front: growing vectors of millions of entries cost more than filling them. The
  // pattern keeps an element's lower triangle (3n (3n + 1) / 2 of its (3n)^2 entries).
  const size_t lower = 21 * static_cast<size_t>(s.size()) + 45 * static_cast<size_t>(b.size()) +
                       78 * static_cast<size_t>(h.size());
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(lower + static_cast<size_t>(ndof));
  spring_slots_.reserve(36 * static_cast<size_t>(s.size()));
  bend_slots_.reserve(81 * static_cast<size_t>(b.size()));
  hinge_slots_.reserve(144 * static_cast<size_t>(h.size()));
  diag_slots_.reserve(static_cast<size_t>(ndof));
  auto keep = [&](int r, int c) {
    if (r >= 0 && c >= 0 && r >= c) t.emplace_back(r, c, 0.0);
  };
  for (int i = 0; i < s.size(); ++i) visit_pairs(spring_ends(s, i), dof, keep);
  for (int e = 0; e < b.size(); ++e) visit_pairs(b.v[e], dof, keep);
  for (int e = 0; e < h.size(); ++e) visit_pairs(h.v[e], dof, keep);
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
  for (int i = 0; i < s.size(); ++i) visit_pairs(spring_ends(s, i), dof, slot_of(spring_slots_));
  for (int e = 0; e < b.size(); ++e) visit_pairs(b.v[e], dof, slot_of(bend_slots_));
  for (int e = 0; e < h.size(); ++e) visit_pairs(h.v[e], dof, slot_of(hinge_slots_));
  for (int k = 0; k < ndof; ++k) slot_of(diag_slots_)(k, k);
}

template <int N>
void HessianAssembler::add_block(const Eigen::Matrix<double, 3 * N, 3 * N>& block,
                                 const int* slot) {
  double* val = h_.valuePtr();
  for (int r = 0; r < 3 * N; ++r)
    for (int c = 0; c < 3 * N; ++c, ++slot)
      if (*slot >= 0) val[*slot] += block(r, c);
}

const Eigen::SparseMatrix<double>& HessianAssembler::assemble(const Points& x, bool project) {
  std::fill(h_.valuePtr(), h_.valuePtr() + h_.nonZeros(), 0.0);
  const Springs& s = model_->springs;
  for (int i = 0; i < s.size(); ++i) {
    const Eigen::Matrix3d k = spring_hessian_block(x.col(s.a[i]), x.col(s.b[i]), s.rest_length[i],
                                                   s.stiffness[i], project);
    Eigen::Matrix<double, 6, 6> block;
    block << k, -k, -k, k;
    add_block<2>(block, &spring_slots_[static_cast<size_t>(i) * 36]);
  }
  const Bending& b = model_->bending;
  for (int e = 0; e < b.size(); ++e) {
    const auto& v = b.v[e];
    add_block<3>(bend_hessian(x.col(v[0]), x.col(v[1]), x.col(v[2]), b.stiffness[e], project),
                 &bend_slots_[static_cast<size_t>(e) * 81]);
  }
  const Hinges& h = model_->hinges;
  for (int e = 0; e < h.size(); ++e) {
    if (h.moment[e] == 0.0) continue;
    const auto& v = h.v[e];
    add_block<4>(
        hinge_hessian(x.col(v[0]), x.col(v[1]), x.col(v[2]), x.col(v[3]), h.moment[e], project),
        &hinge_slots_[static_cast<size_t>(e) * 144]);
  }
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
