#include "membra/design/adjoint_solve.hpp"

#include <vector>

#include <Eigen/SparseCholesky>

#include "membra/solve/hessian_assembler.hpp"
#include "membra/solve/rigid_gauge.hpp"

namespace membra {

std::optional<Points> solve_adjoint(const Model& model, const Points& x, const Points& rhs) {
  const int n = model.num_particles();
  bool any_pin = false;
  for (int p = 0; p < n; ++p) any_pin = any_pin || model.pinned(p);
  // Coordinates turned into the gauge frame (identity when pins hold the sheet).
  RigidGauge gauge;
  std::vector<char> held(static_cast<size_t>(3 * n), 0);
  if (any_pin) {
    for (int p = 0; p < n; ++p)
      if (model.pinned(p)) held[3 * p] = held[3 * p + 1] = held[3 * p + 2] = 1;
  } else {
    gauge = free_sheet_gauge(model, x);
    for (int k : gauge.held) held[k] = 1;
  }
  std::vector<int> free_index(held.size(), -1);
  int nfree = 0;
  for (size_t k = 0; k < held.size(); ++k)
    if (!held[k]) free_index[k] = nfree++;
  // Q: the block-diagonal turn; H in the gauge frame is Q H Q^T, restricted to free coordinates.
  std::vector<Eigen::Triplet<double>> q;
  q.reserve(static_cast<size_t>(9 * n));
  for (int p = 0; p < n; ++p)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) q.emplace_back(3 * p + r, 3 * p + c, gauge.rotation(r, c));
  Eigen::SparseMatrix<double> qm(3 * n, 3 * n), select(nfree, 3 * n);
  qm.setFromTriplets(q.begin(), q.end());
  std::vector<Eigen::Triplet<double>> s;
  for (size_t k = 0; k < held.size(); ++k)
    if (!held[k]) s.emplace_back(free_index[k], static_cast<int>(k), 1.0);
  select.setFromTriplets(s.begin(), s.end());
  const Eigen::SparseMatrix<double> turn = select * qm;
  const Eigen::SparseMatrix<double> h = turn * potential_hessian(model, x) * turn.transpose();
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(h);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 0.0)) return std::nullopt;
  const Eigen::Map<const Eigen::VectorXd> r(rhs.data(), rhs.size());
  const Eigen::VectorXd w = turn.transpose() * ldlt.solve(turn * r);
  return Points(Eigen::Map<const Points>(w.data(), 3, n));
}

}  // namespace membra
