#include "membra/solve/static_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "membra/model/forces.hpp"

namespace membra {

std::vector<double> stiffness_scaled_masses(const Model& model, const Points& x) {
  std::vector<double> m(static_cast<size_t>(model.num_particles()), 0.0);
  model.for_each_set([&](const auto& set) { set.add_stiffness_estimate(x, m); });
  for (double& mi : m)
    if (!(mi > 0.0)) mi = 1.0;  // a particle with nothing attached: any mass will do
  return m;
}

StaticRelaxation::StaticRelaxation(const Model& model, const Points& x, const StaticOptions& o)
    : options_(o) {
  reset(model, x);
}

void StaticRelaxation::reset(const Model& model, const Points& x) {
  mass_ = stiffness_scaled_masses(model, x);
  if (options_.uniform_mass && !mass_.empty())
    mass_.assign(mass_.size(), *std::max_element(mass_.begin(), mass_.end()));
  v_ = Points::Zero(3, model.num_particles());
  dt_ = 0.1;
  alpha_ = kAlphaStart;
  n_positive_ = 0;
  iterations_ = 0;
  size0_ = std::max(sheet_extent(x), 1e-12);
  f_.resize(3, 0);
  x_of_f_.resize(3, 0);
}

namespace {

std::string divergence_message(long it, bool finite) {
  std::ostringstream msg;
  msg << "static solver diverged at iteration " << it << ": "
      << (finite ? "the sheet blew up (100x its size)" : "forces became NaN/Inf")
      << ". Check for coincident particles or extreme stiffness contrast, give a free sheet "
         "pins, or try rk4 with damping D.";
  return msg.str();
}

}  // namespace

void StaticRelaxation::fire_step(const Model& model, Points& x, const Points& f, long it) {
  // FIRE 2.0 parameters (dimensionless: masses are stiffnesses, so time is in units of 1/omega).
  constexpr double dt_max = 1.0, dt_min = 0.02, f_inc = 1.1, f_dec = 0.5;
  constexpr double f_alpha = 0.99;
  constexpr int n_delay = 20;

  const int n = model.num_particles();
  Points& v = v_;
  const std::vector<double>& mass = mass_;
  // Power of the forces on the current velocities decides: speed up, or stop and back off.
  double power = 0.0, v_norm2 = 0.0, g_norm2 = 0.0;
  for (int p = 0; p < n; ++p) {
    if (model.pinned(p)) continue;
    power += f.col(p).dot(v.col(p));
    v_norm2 += mass[p] * v.col(p).squaredNorm();
    g_norm2 += f.col(p).squaredNorm() / mass[p];
  }
  if (power > 0.0) {
    if (++n_positive_ > n_delay) {
      dt_ = std::min(dt_ * f_inc, dt_max);
      alpha_ *= f_alpha;
    }
  } else {
    n_positive_ = 0;
    if (it > n_delay) dt_ = std::max(dt_ * f_dec, dt_min);
    alpha_ = kAlphaStart;
    x -= 0.5 * dt_ * v;  // undo half of the overshooting step
    v.setZero();
  }
  // Semi-implicit Euler on the scaled masses, with FIRE's steering of v towards the force
  // (done in the mass-weighted metric, where the scaled system is isotropic).
  const double mix = g_norm2 > 0.0 ? alpha_ * std::sqrt(v_norm2 / g_norm2) : 0.0;
  for (int p = 0; p < n; ++p) {
    if (model.pinned(p)) continue;
    const Vec3 a = f.col(p) / mass[p];
    v.col(p) = (1.0 - alpha_) * (v.col(p) + dt_ * a) + mix * a;
    x.col(p) += dt_ * v.col(p);
  }
}

SolveReport StaticRelaxation::advance(const Model& model, State& state, long iterations) {
  const Stopwatch clock;
  auto seconds = [&] { return clock.seconds(); };
  const StaticOptions& o = options_;
  const int n = model.num_particles();
  if (v_.cols() != n || static_cast<int>(mass_.size()) != n) reset(model, state.x);

  Points& x = state.x;
  Points f;
  SolveReport r;
  // The forces the last call ended with, where the sheet has not moved since (a viewer's slices:
  // on a large mesh a slice is one iteration, and this pass was half of it). The model is the
  // same until reset(), so they are the forces a new pass would give, bit for bit.
  if (x_of_f_.cols() == x.cols() && x_of_f_ == x)
    f = f_;
  else
    compute_static_forces(model, x, f);
  for (long k = 1; k <= iterations; ++k) {
    const long it = ++iterations_;
    fire_step(model, x, f, it);
    compute_static_forces(model, x, f);
    ++r.iterations;
    ++r.force_passes;
    // The clock every iteration: on a large mesh check_every iterations outlast a viewer's slice.
    const bool out_of_time = o.max_seconds > 0.0 && seconds() > o.max_seconds;
    if (k % o.check_every != 0 && k != iterations && !out_of_time) continue;

    const double res = max_free_force(model, f);
    r.residual = res;
    r.residual_relative = res / o.force_scale;
    if (!std::isfinite(res) || !x.allFinite() || sheet_extent(x) > 100.0 * size0_) {
      r.diverged = true;
      r.message = divergence_message(it, std::isfinite(res) && x.allFinite());
      r.wall_seconds = seconds();
      return r;
    }
    if (o.progress) o.progress({"", k, iterations, r.residual_relative, seconds(), -1.0, -1.0});
    if (r.residual_relative <= o.tolerance || out_of_time) break;
  }
  if (r.iterations == 0) {
    const double res = max_free_force(model, f);
    r.residual = res;
    r.residual_relative = res / o.force_scale;
  }
  r.converged = r.residual_relative <= o.tolerance;
  r.wall_seconds = seconds();
  r.message = summary_message("static", r, o.tolerance);
  f_ = std::move(f);
  x_of_f_ = x;
  return r;
}

SolveReport solve_static(const Model& model, State& state, const StaticOptions& o) {
  StaticRelaxation relaxation(model, state.x, o);
  SolveReport r = relaxation.advance(model, state, o.max_iterations);
  state.v.setZero(3, model.num_particles());
  return r;
}

}  // namespace membra
