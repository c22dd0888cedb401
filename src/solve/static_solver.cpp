#include "membra/solve/static_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "membra/model/forces.hpp"

namespace membra {

std::vector<double> stiffness_scaled_masses(const Model& model, const Points& x) {
  std::vector<double> m(static_cast<size_t>(model.num_particles()), 0.0);
  const Springs& s = model.springs;
  for (int i = 0; i < s.size(); ++i) {
    const double l = (x.col(s.b[i]) - x.col(s.a[i])).norm();
    // Axial stiffness k plus the geometric (stress) stiffness |k (1 - l0/l)| across the spring.
    const double k =
        s.stiffness[i] * (1.0 + (l > 0.0 ? std::abs(1.0 - s.rest_length[i] / l) : 1.0));
    m[s.a[i]] += k;
    m[s.b[i]] += k;
  }
  const Bending& b = model.bending;
  for (int i = 0; i < b.size(); ++i) {
    // Small-angle energy c |x0 - 2 x1 + x2|^2 / L^2: Hessian row sums 8c/L^2 (ends), 16c/L^2
    // (node).
    const auto& v = b.v[i];
    const double l2 = 0.25 * (x.col(v[2]) - x.col(v[0])).squaredNorm();
    if (l2 <= 0.0) continue;
    const double k = 8.0 * b.stiffness[i] / l2;
    m[v[0]] += k;
    m[v[1]] += 2.0 * k;
    m[v[2]] += k;
  }
  for (double& mi : m)
    if (!(mi > 0.0)) mi = 1.0;  // a particle with nothing attached: any mass will do
  return m;
}

SolveReport solve_static(const Model& model, State& state, const StaticOptions& o) {
  const Stopwatch clock;
  auto seconds = [&] { return clock.seconds(); };
  const int n = model.num_particles();
  std::vector<double> mass = stiffness_scaled_masses(model, state.x);
  if (o.uniform_mass && !mass.empty())
    mass.assign(mass.size(), *std::max_element(mass.begin(), mass.end()));

  // FIRE 2.0 parameters (dimensionless: masses are stiffnesses, so time is in units of 1/omega).
  constexpr double dt_max = 1.0, dt_min = 0.02, f_inc = 1.1, f_dec = 0.5;
  constexpr double alpha_start = 0.25, f_alpha = 0.99;
  constexpr int n_delay = 20;
  double dt = 0.1, alpha = alpha_start;
  int n_positive = 0;

  Points& x = state.x;
  const double size0 = std::max(sheet_extent(x), 1e-12);
  Points v = Points::Zero(3, n), f;
  SolveReport r;
  compute_static_forces(model, x, f);
  for (long it = 1; it <= o.max_iterations; ++it) {
    // Power of the forces on the current velocities decides: speed up, or stop and back off.
    double power = 0.0, v_norm2 = 0.0, g_norm2 = 0.0;
    for (int p = 0; p < n; ++p) {
      if (model.pinned(p)) continue;
      power += f.col(p).dot(v.col(p));
      v_norm2 += mass[p] * v.col(p).squaredNorm();
      g_norm2 += f.col(p).squaredNorm() / mass[p];
    }
    if (power > 0.0) {
      if (++n_positive > n_delay) {
        dt = std::min(dt * f_inc, dt_max);
        alpha *= f_alpha;
      }
    } else {
      n_positive = 0;
      if (it > n_delay) dt = std::max(dt * f_dec, dt_min);
      alpha = alpha_start;
      x -= 0.5 * dt * v;  // undo half of the overshooting step
      v.setZero();
    }
    // Semi-implicit Euler on the scaled masses, with FIRE's steering of v towards the force
    // (done in the mass-weighted metric, where the scaled system is isotropic).
    const double mix = g_norm2 > 0.0 ? alpha * std::sqrt(v_norm2 / g_norm2) : 0.0;
    for (int p = 0; p < n; ++p) {
      if (model.pinned(p)) continue;
      const Vec3 a = f.col(p) / mass[p];
      v.col(p) = (1.0 - alpha) * (v.col(p) + dt * a) + mix * a;
      x.col(p) += dt * v.col(p);
    }
    compute_static_forces(model, x, f);
    ++r.iterations;
    ++r.force_passes;
    if (it % o.check_every != 0 && it != o.max_iterations) continue;

    const double res = max_free_force(model, f);
    r.residual = res;
    r.residual_relative = res / o.force_scale;
    if (!std::isfinite(res) || !x.allFinite() || sheet_extent(x) > 100.0 * size0) {
      r.diverged = true;
      std::ostringstream msg;
      msg << "static solver diverged at iteration " << it << ": "
          << (std::isfinite(res) && x.allFinite() ? "the sheet blew up (100x its size)"
                                                  : "forces became NaN/Inf")
          << ". Check for coincident particles or extreme stiffness contrast, give a free "
             "sheet pins, or try rk4 with damping D.";
      r.message = msg.str();
      r.wall_seconds = seconds();
      return r;
    }
    if (o.progress) o.progress({"", it, o.max_iterations, r.residual_relative, seconds()});
    if (r.residual_relative <= o.tolerance) break;
    if (o.max_seconds > 0.0 && seconds() > o.max_seconds) break;
  }
  if (r.iterations == 0) {
    const double res = max_free_force(model, f);
    r.residual = res;
    r.residual_relative = res / o.force_scale;
  }
  r.converged = r.residual_relative <= o.tolerance;
  state.v.setZero(3, n);
  r.wall_seconds = seconds();
  r.message = summary_message("static", r, o.tolerance);
  return r;
}

}  // namespace membra
