// Solver candidates that were measured on P(n) and not kept, and the spectrum that explains why
// (docs/performance.md, "The speed goal"). Kept so that the numbers there can be reproduced:
//
//   membra_solver_experiments spectrum N          FIRE to 1e-6, then the mass-scaled Hessian's
//                                                 extreme eigenvalues and the first-order bound
//   membra_solver_experiments lbfgs-tail N [m]    FIRE to 1e-4, then FIRE or L-BFGS to 1e-6
//   membra_solver_experiments continuation N L    P on coarser grids of the same extent first
//   membra_solver_experiments trust-region N S M  trust-region Newton-CG (Steihaug), Cholesky of
//                                                 the projected Hessian as preconditioner, from
//                                                 FIRE's state at residual S (0: the flat start),
//                                                 at most M outer steps
//
// Single-threaded comparisons: run with OMP_NUM_THREADS=1.
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <numbers>
#include <string>
#include <vector>

#include "membra/model/benchmark_problem.hpp"
#include "membra/model/forces.hpp"
#include "membra/solve/solve_report.hpp"
#include "membra/solve/static_solver.hpp"

namespace {

using membra::Model;
using membra::Points;
using membra::Vec3;
using Vec = Eigen::VectorXd;
using SpMat = Eigen::SparseMatrix<double>;

// Springs-only Hessian of the potential energy (P(n) has no other elements). `project` drops the
// negative geometric stiffness of compressed springs, leaving a positive semi-definite matrix.
SpMat spring_hessian(const Model& m, const Points& x, bool project) {
  std::vector<Eigen::Triplet<double>> t;
  const membra::Springs& s = m.springs;
  t.reserve(static_cast<size_t>(s.size()) * 36);
  for (int i = 0; i < s.size(); ++i) {
    const Vec3 d = x.col(s.b[i]) - x.col(s.a[i]);
    const double l = d.norm();
    const Vec3 n = d / l;
    const double axial = s.rest_length[i] / l;
    const double geo = project ? std::max(1.0 - axial, 0.0) : 1.0 - axial;
    const Eigen::Matrix3d k =
        s.stiffness[i] * (axial * n * n.transpose() + geo * Eigen::Matrix3d::Identity());
    const int p[2] = {s.a[i], s.b[i]};
    for (int A = 0; A < 2; ++A)
      for (int B = 0; B < 2; ++B)
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c)
            t.emplace_back(3 * p[A] + r, 3 * p[B] + c, (A == B ? 1.0 : -1.0) * k(r, c));
  }
  SpMat h(3 * x.cols(), 3 * x.cols());
  h.setFromTriplets(t.begin(), t.end());
  return h;
}

// Selects the free coordinates of a released n x n sheet: six coordinates of three particles are
// held (the gauge), which removes the rigid motions and nothing else.
SpMat gauge_selection(int n) {
  const int N = n * n, a = (n / 2) * n + n / 2, b = (n / 2) * n + n - 1, c = (n - 1) * n + n / 2;
  std::vector<int> held{3 * a, 3 * a + 1, 3 * a + 2, 3 * b + 1, 3 * b + 2, 3 * c + 2};
  std::vector<Eigen::Triplet<double>> t;
  int row = 0;
  for (int k = 0; k < 3 * N; ++k)
    if (std::find(held.begin(), held.end(), k) == held.end()) t.emplace_back(row++, k, 1.0);
  SpMat s(row, 3 * N);
  s.setFromTriplets(t.begin(), t.end());
  return s;
}

double max_norm3(const Vec& full) {
  double r = 0.0;
  for (Eigen::Index p = 0; p + 2 < full.size(); p += 3) r = std::max(r, full.segment<3>(p).norm());
  return r;
}

membra::SolveReport fire(const Model& m, membra::State& st, double tolerance) {
  membra::StaticOptions o;
  o.tolerance = tolerance;
  return membra::solve_static(m, st, o);
}

// FIRE to 1e-6, then the extreme eigenvalues of D^-1 H (D: the stiffness-scaled masses, H: the
// Hessian over the free coordinates). A first-order method with momentum (heavy ball, CG, FIRE)
// needs at least ~1.15 sqrt(kappa) iterations per decade of residual on such a spectrum.
int spectrum(int n) {
  const membra::BenchmarkProblem P = membra::make_benchmark_problem(n);
  membra::State st = P.start;
  const membra::SolveReport r = fire(P.model, st, 1e-6);
  std::printf("P(%d) FIRE: %ld iterations, %.2f s, max|f| %.2e\n", n, r.iterations, r.wall_seconds,
              r.residual);
  const SpMat S = gauge_selection(n);
  const SpMat H = S * spring_hessian(P.model, st.x, false) * S.transpose();
  const std::vector<double> mass = membra::stiffness_scaled_masses(P.model, st.x);
  Vec dfull(3 * n * n);
  for (int p = 0; p < n * n; ++p) dfull.segment<3>(3 * p).setConstant(mass[static_cast<size_t>(p)]);
  const Vec d = S * dfull;
  Eigen::CholmodSupernodalLLT<SpMat> llt;
  llt.cholmod().print = 0;
  llt.analyzePattern(H);
  // Sylvester: H - sigma D is positive definite exactly when sigma < lambda_min(D^-1 H).
  auto definite = [&](double sigma) {
    SpMat a = H;
    for (Eigen::Index k = 0; k < a.rows(); ++k) a.coeffRef(k, k) -= sigma * d[k];
    llt.factorize(a);
    return llt.info() == Eigen::Success;
  };
  double lo = 0.0, hi = 0.0;
  if (definite(0.0)) {
    hi = 1e-14;
    while (definite(hi)) lo = hi, hi *= 2.0;
  } else {
    lo = -1e-14;
    while (!definite(lo)) hi = lo, lo *= 2.0;
  }
  for (int k = 0; k < 40; ++k) (definite(0.5 * (lo + hi)) ? lo : hi) = 0.5 * (lo + hi);
  Vec v = Vec::Ones(d.size());
  double lmax = 0.0;
  for (int k = 0; k < 300; ++k) {
    const Vec w = (H * v).cwiseQuotient(d);
    lmax = w.norm() / v.norm();
    v = w / w.norm();
  }
  std::printf("lambda_min(D^-1 H) = %.3g, lambda_max = %.3g", 0.5 * (lo + hi), lmax);
  if (lo > 0.0) {
    const double kappa = lmax / lo;
    std::printf(", kappa = %.3g: a first-order method needs >= %.0f iterations per decade\n", kappa,
                1.15 * std::sqrt(kappa));
  } else {
    std::printf(": a saddle, not a minimum\n");
  }
  return 0;
}

// Preconditioned L-BFGS (H0 = gamma D^-1, two-loop recursion, Armijo backtracking with a cap of
// half a spacing per particle) from x to max|f| < 1e-6.
void lbfgs(const Model& m, Points& X, const std::vector<double>& mass, int memory) {
  const membra::Stopwatch clock;
  const int N = m.num_particles();
  Eigen::Map<Vec> x(X.data(), 3 * N);
  Vec dinv(3 * N);
  for (int p = 0; p < N; ++p)
    dinv.segment<3>(3 * p).setConstant(1.0 / mass[static_cast<size_t>(p)]);
  Points f;
  long passes = 0;
  auto eval = [&](double& e, Vec& g) {
    membra::compute_static_forces(m, X, f);
    ++passes;
    e = membra::potential_energy(m, X);
    g = -Eigen::Map<const Vec>(f.data(), 3 * N);
  };
  double e = 0.0;
  Vec g;
  eval(e, g);
  std::deque<Vec> S, Y;
  std::deque<double> R;
  while (max_norm3(g) >= 1e-6 && passes < 2000000) {
    Vec q = g;
    std::vector<double> a(S.size());
    for (size_t i = S.size(); i-- > 0;) {
      a[i] = R[i] * S[i].dot(q);
      q -= a[i] * Y[i];
    }
    const double gamma =
        S.empty() ? 1.0 : S.back().dot(Y.back()) / Y.back().dot(dinv.cwiseProduct(Y.back()));
    Vec dir = gamma * dinv.cwiseProduct(q);
    for (size_t i = 0; i < S.size(); ++i) dir += S[i] * (a[i] - R[i] * Y[i].dot(dir));
    dir = -dir;
    double slope = g.dot(dir);
    if (slope >= 0.0) {
      dir = -dinv.cwiseProduct(g);
      slope = g.dot(dir);
      S.clear(), Y.clear(), R.clear();
    }
    double alpha = std::min(1.0, 0.5 / max_norm3(dir));
    const Vec x0 = x, g0 = g;
    const double e0 = e;
    for (int ls = 0; ls < 30; ++ls, alpha *= 0.5) {
      x = x0 + alpha * dir;
      eval(e, g);
      if (e <= e0 + 1e-4 * alpha * slope + 1e-13 * std::abs(e0)) break;
    }
    const Vec s = x - x0, y = g - g0;
    const double sy = s.dot(y);
    if (sy > 1e-12 * s.norm() * y.norm()) {
      S.push_back(s), Y.push_back(y), R.push_back(1.0 / sy);
      if (static_cast<int>(S.size()) > memory) S.pop_front(), Y.pop_front(), R.pop_front();
    }
  }
  std::printf("L-BFGS (m = %d) tail: %ld force passes, %.2f s, max|f| %.2e, energy %.6f\n", memory,
              passes, clock.seconds(), max_norm3(g), e);
}

int lbfgs_tail(int n, int memory) {
  const membra::BenchmarkProblem P = membra::make_benchmark_problem(n);
  membra::State st = P.start;
  membra::SolveReport r = fire(P.model, st, 1e-4);
  std::printf("P(%d) FIRE to 1e-4: %ld iterations, %.2f s\n", n, r.iterations, r.wall_seconds);
  membra::State tail = st;
  r = fire(P.model, tail, 1e-6);
  std::printf("FIRE tail: %ld force passes, %.2f s, max|f| %.2e, energy %.6f\n", r.force_passes,
              r.wall_seconds, r.residual, membra::potential_energy(P.model, tail.x));
  lbfgs(P.model, st.x, membra::stiffness_scaled_masses(P.model, st.x), memory);
  return 0;
}

// P's sheet on nc x nc nodes spanning the extent of P(n): same ellipse, same spring constants.
membra::BenchmarkProblem coarse_problem(int n, int nc) {
  membra::BenchmarkProblem b;
  Model& m = b.model;
  const int np = nc * nc;
  const double L = n - 1, h = L / (nc - 1), pi = std::numbers::pi;
  m.mass.assign(static_cast<size_t>(np), 1.0);
  m.inv_mass.assign(static_cast<size_t>(np), 1.0);
  m.reference = Points::Zero(3, np);
  Points x(3, np);
  for (int j = 0; j < nc; ++j)
    for (int i = 0; i < nc; ++i) {
      m.reference.col(j * nc + i) = Vec3(i * h, j * h, 0.0);
      x.col(j * nc + i) =
          Vec3(i * h, j * h, 1e-3 * std::sin(pi * i * h / n) * std::sin(pi * j * h / n));
    }
  const double ax = 0.35 * n, ay = 0.2 * n;
  auto connect = [&](int i0, int j0, int i1, int j1, double k, membra::SpringFamily fam) {
    if (i1 < 0 || i1 >= nc || j1 < 0 || j1 >= nc) return;
    const int a = j0 * nc + i0, c = j1 * nc + i1;
    const double len = (x.col(c) - x.col(a)).norm();
    const double mx = 0.5 * (i0 + i1) * h - 0.5 * L, my = 0.5 * (j0 + j1) * h - 0.5 * L;
    const bool inside = (mx / ax) * (mx / ax) + (my / ay) * (my / ay) < 1.0;
    m.springs.add(a, c, inside ? len : len / 1.5, inside ? 50.0 * k : k, 0.0, fam);
  };
  for (int j = 0; j < nc; ++j)
    for (int i = 0; i < nc; ++i) {
      connect(i, j, i + 1, j, 1.0, membra::SpringFamily::stretch);
      connect(i, j, i, j + 1, 1.0, membra::SpringFamily::stretch);
      connect(i, j, i + 1, j + 1, 0.5, membra::SpringFamily::shear);
      if (i + 1 < nc) connect(i + 1, j, i, j + 1, 0.5, membra::SpringFamily::shear);
      connect(i, j, i + 2, j, 0.1, membra::SpringFamily::flex);
      connect(i, j, i, j + 2, 0.1, membra::SpringFamily::flex);
    }
  b.n = nc;
  b.start = membra::State::at_rest(m);
  b.start.x = x;
  return b;
}

// Bilinear prolongation between grids of the same extent.
Points prolong(const Points& xc, int nc, int nf) {
  Points xf(3, nf * nf);
  const double ratio = double(nc - 1) / (nf - 1);
  for (int j = 0; j < nf; ++j)
    for (int i = 0; i < nf; ++i) {
      const double u = i * ratio, v = j * ratio;
      const int i0 = std::min(static_cast<int>(u), nc - 2),
                j0 = std::min(static_cast<int>(v), nc - 2);
      const double a = u - i0, b = v - j0;
      xf.col(j * nf + i) =
          (1 - a) * (1 - b) * xc.col(j0 * nc + i0) + a * (1 - b) * xc.col(j0 * nc + i0 + 1) +
          (1 - a) * b * xc.col((j0 + 1) * nc + i0) + a * b * xc.col((j0 + 1) * nc + i0 + 1);
    }
  return xf;
}

int continuation(int n, int levels, double coarse_tolerance) {
  std::vector<int> sizes{n};
  for (int l = 0; l < levels; ++l) sizes.push_back((sizes.back() + 1) / 2);
  const membra::Stopwatch clock;
  Points x;
  int previous = 0;
  for (int l = levels; l >= 0; --l) {
    const int nc = sizes[static_cast<size_t>(l)];
    membra::BenchmarkProblem P = coarse_problem(n, nc);
    if (l < levels) P.start.x = prolong(x, previous, nc);
    const membra::SolveReport r = fire(P.model, P.start, l == 0 ? 1e-6 : coarse_tolerance);
    std::printf("%d x %d: %ld iterations, %.2f s, max|f| %.1e, energy %.4f\n", nc, nc, r.iterations,
                r.wall_seconds, r.residual, membra::potential_energy(P.model, P.start.x));
    x = P.start.x;
    previous = nc;
  }
  std::printf("continuation total: %.2f s\n", clock.seconds());
  membra::BenchmarkProblem P = membra::make_benchmark_problem(n);
  const membra::SolveReport r = fire(P.model, P.start, 1e-6);
  std::printf("plain FIRE on P(%d): %ld iterations, %.2f s, energy %.4f\n", n, r.iterations,
              r.wall_seconds, membra::potential_energy(P.model, P.start.x));
  return 0;
}

// Trust-region Newton-CG (Steihaug-Toint) in the norm of the preconditioner M = projected Hessian
// x (1 + 1e-2) on its diagonal; M is factorized (CHOLMOD) every outer step, which is the best a
// multigrid preconditioner could do per step: the outer step count is what this measures.
int trust_region(int n, double start_tolerance, long max_outer) {
  const membra::BenchmarkProblem P = membra::make_benchmark_problem(n);
  const Model& m = P.model;
  membra::State st = P.start;
  if (start_tolerance > 0.0) {
    const membra::SolveReport r = fire(m, st, start_tolerance);
    std::printf("P(%d) FIRE to %g: %ld iterations, %.2f s\n", n, start_tolerance, r.iterations,
                r.wall_seconds);
  }
  const membra::Stopwatch clock;
  Points& X = st.x;
  const int N = m.num_particles();
  const SpMat S = gauge_selection(n);
  auto gradient = [&](const Points& x) {
    Points f;
    membra::compute_static_forces(m, x, f);
    return Vec(-(S * Eigen::Map<const Vec>(f.data(), 3 * N)));
  };
  auto residual = [&](const Vec& g) { return max_norm3(S.transpose() * g); };
  Eigen::CholmodSupernodalLLT<SpMat> llt;
  llt.cholmod().print = 0;
  bool analysed = false;
  Vec g = gradient(X);
  double e = membra::potential_energy(m, X), radius = 1.0;
  long outer = 0, cg = 0;
  for (; outer < max_outer && residual(g) >= 1e-6; ++outer) {
    const SpMat H = S * spring_hessian(m, X, false) * S.transpose();
    SpMat M = S * spring_hessian(m, X, true) * S.transpose();
    for (Eigen::Index k = 0; k < M.rows(); ++k) M.coeffRef(k, k) *= 1.0 + 1e-2;
    if (!analysed) llt.analyzePattern(M), analysed = true;
    llt.factorize(M);
    if (llt.info() != Eigen::Success) {
      std::printf("the preconditioner's factorization failed\n");
      return 1;
    }
    auto mnorm2 = [&](const Vec& v) { return v.dot(M * v); };
    auto to_boundary = [&](const Vec& s0, const Vec& p0) {
      const double pp = mnorm2(p0), sp = s0.dot(M * p0), ss = mnorm2(s0);
      return Vec(s0 + (-sp + std::sqrt(sp * sp + pp * (radius * radius - ss))) / pp * p0);
    };
    Vec s = Vec::Zero(g.size()), r = g, z = llt.solve(r), p = -z;
    double rz = r.dot(z);
    const double eta = std::min(0.5, std::sqrt(g.norm())) * g.norm();
    bool boundary = false;
    for (int j = 0; j < 500; ++j) {
      ++cg;
      const Vec hp = H * p;
      const double curvature = p.dot(hp);
      if (curvature <= 0.0) {  // negative curvature: go to the boundary along it
        s = to_boundary(s, p), boundary = true;
        break;
      }
      const double alpha = rz / curvature;
      if (mnorm2(s + alpha * p) >= radius * radius) {
        s = to_boundary(s, p), boundary = true;
        break;
      }
      s += alpha * p;
      r += alpha * hp;
      if (r.norm() <= eta) break;
      z = llt.solve(r);
      const double rz_next = r.dot(z);
      p = -z + (rz_next / rz) * p;
      rz = rz_next;
    }
    Points trial = X;
    const Vec step = S.transpose() * s;
    trial += Eigen::Map<const Points>(step.data(), 3, N);
    const double e_trial = membra::potential_energy(m, trial);
    const Vec g_trial = gradient(trial);
    const double predicted = g.dot(s) + 0.5 * s.dot(H * s);
    const double rho = (e_trial - e) / predicted;
    const bool roundoff =
        std::abs(e_trial - e) < 1e-12 * std::abs(e) && residual(g_trial) < residual(g);
    if (rho < 0.25)
      radius *= 0.25;
    else if (rho > 0.75 && boundary)
      radius *= 2.0;
    if (rho > 0.1 || roundoff) X = trial, g = g_trial, e = e_trial;
    if (outer % 50 == 0)
      std::printf("  step %ld: max|f| %.2e, energy %.6f, radius %.2e, %.2f s\n", outer, residual(g),
                  e, radius, clock.seconds());
  }
  std::printf(
      "trust-region Newton-CG: %ld outer steps (%ld Hessian products), %.2f s, max|f| "
      "%.2e, energy %.6f\n",
      outer, cg, clock.seconds(), residual(g), e);
  return 0;
}

int usage() {
  std::fprintf(stderr,
               "usage: membra_solver_experiments spectrum N | lbfgs-tail N [memory=10] |\n"
               "       continuation N [levels=1] [coarse_tolerance=1e-4] |\n"
               "       trust-region N [start_tolerance=1e-4] [max_outer=2000]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return usage();
  const std::string what = argv[1];
  const int n = std::stoi(argv[2]);
  if (n < 8) return usage();
  auto arg = [&](int i, double fallback) { return argc > i ? std::stod(argv[i]) : fallback; };
  if (what == "spectrum") return spectrum(n);
  if (what == "lbfgs-tail") return lbfgs_tail(n, static_cast<int>(arg(3, 10)));
  if (what == "continuation") return continuation(n, static_cast<int>(arg(3, 1)), arg(4, 1e-4));
  if (what == "trust-region") return trust_region(n, arg(3, 1e-4), static_cast<long>(arg(4, 2000)));
  return usage();
}
