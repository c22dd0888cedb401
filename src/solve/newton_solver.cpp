#include "membra/solve/newton_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include <Eigen/CholmodSupport>

#include <dlfcn.h>
#include <Eigen/Eigenvalues>
#include <Eigen/SparseCore>

#include "membra/model/bend_kernel.hpp"
#include "membra/model/forces.hpp"
#include "membra/model/hinge_kernel.hpp"

namespace membra {
namespace {

// The supernodal factorization calls BLAS; OpenBLAS's threads spin against the force passes'
// and against other work (3x the wall time measured on a busy 2-core machine: 59 s against 41 s
// for exp2) and make the sums, so the results, depend on the thread count. One BLAS thread keeps
// Newton deterministic and no slower on these sizes. This sets OpenBLAS's process-wide thread
// count, when OpenBLAS is the BLAS in use (found by name, so any other BLAS works unchanged).
void single_threaded_blas() {
  static const bool once = [] {
    using SetThreads = void (*)(int);
    if (auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
      set(1);
    return true;
  }();
  (void)once;
}

// The Hessian's sparsity is fixed during a solve: it is built once, with, for every element,
// the positions of its entries in the matrix's value array, so that each assembly only adds
// numbers (no triplet sorting).
class HessianAssembler {
 public:
  HessianAssembler(const Model& model, const std::vector<int>& dof, int ndof) : model_(model) {
    std::vector<Eigen::Triplet<double>> t;
    auto visit = [&](auto&& ps, auto&& emit) {
      for (size_t r = 0; r < 3 * ps.size(); ++r)
        for (size_t c = 0; c < 3 * ps.size(); ++c) {
          const int dr = dof[3 * ps[r / 3] + r % 3], dc = dof[3 * ps[c / 3] + c % 3];
          emit(dr, dc);
        }
    };
    const Springs& s = model.springs;
    for (int i = 0; i < s.size(); ++i)
      visit(std::array<int, 2>{s.a[i], s.b[i]}, [&](int dr, int dc) {
        if (dr >= 0 && dc >= 0) t.emplace_back(dr, dc, 0.0);
      });
    const Bending& b = model.bending;
    for (int e = 0; e < b.size(); ++e)
      visit(std::array<int, 3>{b.v[e][0], b.v[e][1], b.v[e][2]}, [&](int dr, int dc) {
        if (dr >= 0 && dc >= 0) t.emplace_back(dr, dc, 0.0);
      });
    const Hinges& h = model.hinges;
    for (int e = 0; e < h.size(); ++e)
      visit(h.v[e], [&](int dr, int dc) {
        if (dr >= 0 && dc >= 0) t.emplace_back(dr, dc, 0.0);
      });
    for (int k = 0; k < ndof; ++k) t.emplace_back(k, k, 0.0);  // room for the shift
    h_.resize(ndof, ndof);
    h_.setFromTriplets(t.begin(), t.end());
    h_.makeCompressed();
    auto index = [&](int dr, int dc) {
      if (dr < 0 || dc < 0) return -1;
      const int* begin = h_.innerIndexPtr() + h_.outerIndexPtr()[dc];
      const int* end = h_.innerIndexPtr() + h_.outerIndexPtr()[dc + 1];
      return static_cast<int>(std::lower_bound(begin, end, dr) - h_.innerIndexPtr());
    };
    for (int i = 0; i < s.size(); ++i)
      visit(std::array<int, 2>{s.a[i], s.b[i]},
            [&](int dr, int dc) { spring_slots_.push_back(index(dr, dc)); });
    for (int e = 0; e < b.size(); ++e)
      visit(std::array<int, 3>{b.v[e][0], b.v[e][1], b.v[e][2]},
            [&](int dr, int dc) { bend_slots_.push_back(index(dr, dc)); });
    for (int e = 0; e < h.size(); ++e)
      visit(h.v[e], [&](int dr, int dc) { hinge_slots_.push_back(index(dr, dc)); });
    for (int k = 0; k < ndof; ++k) diag_slots_.push_back(index(k, k));
  }

  // The Hessian of the potential energy at x, plus mu on the diagonal.
  const Eigen::SparseMatrix<double>& assemble(const Points& x, double mu) {
    double* val = h_.valuePtr();
    std::fill(val, val + h_.nonZeros(), 0.0);
    const Springs& s = model_.springs;
    for (int i = 0; i < s.size(); ++i) {
      const Vec3 d = x.col(s.b[i]) - x.col(s.a[i]);
      const double l = d.norm();
      if (l <= 0.0) continue;
      const Vec3 n = d / l;
      // k [n n^T + (1 - l0/l)(I - n n^T)]: axial stiffness plus the geometric (stress) part,
      // negative for a compressed spring.
      const double geo = 1.0 - s.rest_length[i] / l;
      const Eigen::Matrix3d k =
          s.stiffness[i] * ((1.0 - geo) * n * n.transpose() + geo * Eigen::Matrix3d::Identity());
      const int* slot = &spring_slots_[static_cast<size_t>(i) * 36];
      for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 6; ++c, ++slot)
          if (*slot >= 0) val[*slot] += ((r < 3) == (c < 3) ? 1.0 : -1.0) * k(r % 3, c % 3);
    }
    const Bending& b = model_.bending;
    for (int e = 0; e < b.size(); ++e) {
      const auto& v = b.v[e];
      add_fd_block<3>(x, v, 1e-6 * (x.col(v[2]) - x.col(v[0])).norm(), 1.0,
                      &bend_slots_[static_cast<size_t>(e) * 81], val,
                      [&](const std::array<Vec3, 3>& p) {
                        return bend_eval(p[0], p[1], p[2], b.stiffness[e]).grad;
                      });
    }
    const Hinges& h = model_.hinges;
    for (int e = 0; e < h.size(); ++e) {
      if (h.moment[e] == 0.0) continue;
      const auto& v = h.v[e];
      add_fd_block<4>(
          x, v, 1e-6 * (x.col(v[1]) - x.col(v[0])).norm(), h.moment[e],
          &hinge_slots_[static_cast<size_t>(e) * 144], val,
          [](const std::array<Vec3, 4>& p) { return hinge_eval(p[0], p[1], p[2], p[3]).grad; });
    }
    for (int k : diag_slots_) val[k] += mu;
    return h_;
  }

  // Adds the Hessian of an element over particles v, by central differences of its analytic
  // gradient `grad` times `scale` (~1e-8 relative accuracy), symmetrized, into the element's
  // slots.
  template <int N, typename Grad>
  static void add_fd_block(const Points& x, const std::array<int, N>& v, double step, double scale,
                           const int* slot, double* val, Grad grad) {
    if (!(step > 0.0)) return;
    std::array<Vec3, N> p;
    for (int k = 0; k < N; ++k) p[static_cast<size_t>(k)] = x.col(v[static_cast<size_t>(k)]);
    Eigen::Matrix<double, 3 * N, 3 * N> hb;
    for (int c = 0; c < 3 * N; ++c) {
      auto pp = p, pm = p;
      pp[static_cast<size_t>(c / 3)][c % 3] += step;
      pm[static_cast<size_t>(c / 3)][c % 3] -= step;
      const std::array<Vec3, N> gp = grad(pp), gm = grad(pm);
      for (int r = 0; r < 3 * N; ++r)
        hb(r, c) = scale *
                   (gp[static_cast<size_t>(r / 3)][r % 3] - gm[static_cast<size_t>(r / 3)][r % 3]) /
                   (2 * step);
    }
    for (int r = 0; r < 3 * N; ++r)
      for (int c = 0; c < 3 * N; ++c, ++slot)
        if (*slot >= 0) val[*slot] += 0.5 * (hb(r, c) + hb(c, r));
  }

  // Adds delta to the diagonal of the last assembled matrix.
  const Eigen::SparseMatrix<double>& shift(double delta) {
    for (int k : diag_slots_) h_.valuePtr()[k] += delta;
    return h_;
  }

  // Largest diagonal entry, the scale of the shift.
  double scale() const { return h_.diagonal().cwiseAbs().maxCoeff(); }

 private:
  const Model& model_;
  Eigen::SparseMatrix<double> h_;
  std::vector<int> spring_slots_, bend_slots_, hinge_slots_, diag_slots_;
};

// Six coordinates (3 p + axis) fixing translation and rotation: all of particle a, y and z of b,
// z of c, for a, b, c spread over the sheet and not collinear.
std::vector<int> rigid_gauge(const Points& x) {
  const Vec3 centre = x.rowwise().mean();
  int a = 0, b = 0, c = 0;
  double best_a = 1e300, best_b = -1.0, best_c = -1.0;
  for (Eigen::Index p = 0; p < x.cols(); ++p) {
    const double d = (x.col(p) - centre).squaredNorm();
    if (d < best_a) best_a = d, a = static_cast<int>(p);
  }
  for (Eigen::Index p = 0; p < x.cols(); ++p) {
    const double d = (x.col(p) - x.col(a)).squaredNorm();
    if (d > best_b) best_b = d, b = static_cast<int>(p);
  }
  const Vec3 ab = (x.col(b) - x.col(a)).normalized();
  for (Eigen::Index p = 0; p < x.cols(); ++p) {
    const double d = (x.col(p) - x.col(a)).cross(ab).squaredNorm();
    if (d > best_c) best_c = d, c = static_cast<int>(p);
  }
  return {3 * a, 3 * a + 1, 3 * a + 2, 3 * b + 1, 3 * b + 2, 3 * c + 2};
}

}  // namespace

Eigen::SparseMatrix<double> potential_hessian(const Model& model, const Points& x) {
  std::vector<int> dof(static_cast<size_t>(x.size()));
  for (size_t k = 0; k < dof.size(); ++k) dof[k] = static_cast<int>(k);
  HessianAssembler assembler(model, dof, static_cast<int>(dof.size()));
  return assembler.assemble(x, 0.0);
}

namespace {

// Numbers the free coordinates into `dof` (-1: held) and returns how many there are. A sheet
// with no pins can move rigidly: its Hessian has six zero eigenvalues. Holding six coordinates
// of three particles (the gauge) removes them without changing the equilibrium, since nothing
// else holds the sheet.
int number_dofs(const Model& model, const Points& x, std::vector<int>& dof) {
  const int n = model.num_particles();
  bool any_pinned = false;
  for (int p = 0; p < n; ++p) any_pinned = any_pinned || model.pinned(p);
  dof.assign(static_cast<size_t>(3 * n), 0);
  for (int p = 0; p < n; ++p)
    if (model.pinned(p)) dof[3 * p] = dof[3 * p + 1] = dof[3 * p + 2] = -1;
  if (!any_pinned && n >= 3)
    for (int k : rigid_gauge(x)) dof[k] = -1;
  int ndof = 0;
  for (int& d : dof)
    if (d >= 0) d = ndof++;
  return ndof;
}

// Backtracking (Armijo) on the energy along d from x; near convergence the energy change drowns
// in round-off, so a step that lowers the residual (r.residual) is accepted too. Moves x, f and
// energy and returns true when a step is taken.
bool line_search(const Model& model, const std::vector<int>& dof, const Eigen::VectorXd& d,
                 double slope, Points& x, Points& f, double& energy, SolveReport& r) {
  const int n = model.num_particles();
  double alpha = 1.0;
  for (int ls = 0; ls < 30; ++ls, alpha *= 0.5) {
    Points xt = x;
    for (int k = 0; k < 3 * n; ++k)
      if (dof[k] >= 0) xt.data()[k] += alpha * d[dof[k]];
    const double et = potential_energy(model, xt);
    Points ft;
    compute_static_forces(model, xt, ft);
    ++r.force_passes;
    const bool armijo = et <= energy + 1e-4 * alpha * slope;
    const bool roundoff =
        std::abs(et - energy) <= 1e-12 * std::abs(energy) && max_free_force(model, ft) < r.residual;
    if (std::isfinite(et) && (armijo || roundoff)) {
      x = std::move(xt);
      f = std::move(ft);
      energy = et;
      return true;
    }
  }
  return false;
}

}  // namespace

SolveReport solve_newton(const Model& model, State& state, const NewtonOptions& o) {
  const Stopwatch clock;
  auto seconds = [&] { return clock.seconds(); };
  const int n = model.num_particles();
  Points& x = state.x;
  std::vector<int> dof;
  const int ndof = number_dofs(model, x, dof);

  Points f;
  SolveReport r;
  auto residual = [&](const Points& forces) { return max_free_force(model, forces); };
  compute_static_forces(model, x, f);
  ++r.force_passes;
  double energy = potential_energy(model, x);
  double mu = 0.0;  // Levenberg-Marquardt shift, grown when the factorization or the search fails
  // Supernodal Cholesky: fails (info != Success) exactly when the matrix is not positive definite.
  single_threaded_blas();
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>> ldlt;
  ldlt.cholmod().print = 0;  // "not positive definite" is an expected answer here, not news
  HessianAssembler assembler(model, dof, ndof);
  bool pattern_known = false;

  for (long it = 0;; ++it) {
    r.residual = residual(f);
    r.residual_relative = r.residual / o.force_scale;
    if (!std::isfinite(r.residual)) {
      r.diverged = true;
      r.message = "newton diverged at iteration " + std::to_string(it) +
                  ": forces became NaN/Inf. Try the static solver (the default).";
      break;
    }
    if (o.progress) o.progress({"", it, o.max_iterations, r.residual_relative, seconds()});
    if (r.residual_relative <= o.tolerance || it >= o.max_iterations || ndof == 0) break;
    if (o.max_seconds > 0.0 && seconds() > o.max_seconds) break;

    assembler.assemble(x, 0.0);
    double shifted = 0.0;
    Eigen::VectorXd g(ndof);  // energy gradient = -force
    for (int k = 0; k < 3 * n; ++k)
      if (dof[k] >= 0) g[dof[k]] = -f.data()[k];
    const double scale = assembler.scale();
    mu = mu * 0.25 < 1e-12 * scale ? 0.0 : mu * 0.25;  // trust the model more after success
    ++r.iterations;

    bool stepped = false;
    for (int attempt = 0; attempt < 40 && !stepped; ++attempt) {
      if (attempt > 0) mu = std::max(4.0 * mu, 1e-12 * scale);  // shift more after a failure
      const Eigen::SparseMatrix<double>& a = assembler.shift(mu - shifted);
      shifted = mu;
      if (!pattern_known) ldlt.analyzePattern(a), pattern_known = true;
      ldlt.factorize(a);
      // Only a positive definite system gives a downhill Newton step: otherwise shift more.
      if (ldlt.info() != Eigen::Success) continue;
      const Eigen::VectorXd d = ldlt.solve(-g);
      const double slope = g.dot(d);
      if (!(slope < 0.0)) continue;
      stepped = line_search(model, dof, d, slope, x, f, energy, r);
    }
    if (!stepped) {
      r.message = "newton: no downhill step found at iteration " + std::to_string(it);
      break;
    }
  }
  r.converged = r.residual_relative <= o.tolerance;
  state.v.setZero(3, n);
  r.wall_seconds = seconds();
  if (r.message.empty() || r.converged) r.message = summary_message("newton", r, o.tolerance);
  return r;
}

}  // namespace membra
