#include "membra/solve/stability.hpp"

#include <Eigen/CholmodSupport>
#include <sstream>

#include "membra/solve/hessian_assembler.hpp"
#include "membra/solve/solve_report.hpp"

namespace membra {

StabilityReport check_stability(const Model& model, const Points& x, double stiffness,
                                int max_particles) {
  StabilityReport r;
  const Stopwatch clock;
  const int n = model.num_particles();
  if (n > max_particles) {
    r.message = "not checked: more than " + std::to_string(max_particles) + " particles";
    return r;
  }
  // The Hessian over the free coordinates only.
  const Eigen::SparseMatrix<double> full = potential_hessian(model, x);
  std::vector<int> dof(static_cast<size_t>(3 * n), -1);
  int m = 0;
  for (int p = 0; p < n; ++p)
    if (!model.pinned(p))
      for (int k = 0; k < 3; ++k) dof[3 * p + k] = m++;
  std::vector<Eigen::Triplet<double>> t;
  for (int c = 0; c < full.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(full, c); it; ++it)
      if (dof[it.row()] >= 0 && dof[it.col()] >= 0)
        t.emplace_back(dof[it.row()], dof[it.col()], it.value());
  Eigen::SparseMatrix<double> h(m, m);
  h.setFromTriplets(t.begin(), t.end());
  Eigen::SparseMatrix<double> eye(m, m);
  eye.setIdentity();

  // Simplicial: no BLAS threads to fight the force passes' OpenMP threads (docs/performance.md).
  Eigen::CholmodSimplicialLLT<Eigen::SparseMatrix<double>> llt;
  llt.cholmod().print = 0;  // "not positive definite" is an answer here
  auto positive_definite = [&](double shift) {
    llt.factorize(h + shift * eye);  // the pattern, analysed once below, is the same for all
    return llt.info() == Eigen::Success;
  };
  r.checked = true;
  r.shift = 1e-6 * stiffness;
  llt.analyzePattern(h + r.shift * eye);
  r.stable = m == 0 || positive_definite(r.shift);
  if (!r.stable) {
    // Bracket the smallest eigenvalue: the first shift (doubling) that factorizes.
    double mu = r.shift;
    for (int k = 0; k < 40 && !positive_definite(mu); ++k) mu *= 2.0;
    r.lower_bound = -mu;
    r.min_eigenvalue = -0.5 * mu;
    std::ostringstream msg;
    msg << "unstable: the energy's Hessian has an eigenvalue in (" << -mu << ", " << -0.5 * mu
        << "] N/m; the form is a saddle of the energy and a disturbance would move it (try more "
           "release increments, another perturbation seed, or a dynamic solver)";
    r.message = msg.str();
  } else {
    r.message = "stable: the Hessian + 1e-6 k I is positive definite";
  }
  r.seconds = clock.seconds();
  return r;
}

}  // namespace membra
