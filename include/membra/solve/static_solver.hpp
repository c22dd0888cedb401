#pragma once
// Static equilibrium: FIRE (Bitzek et al. 2006, "Structural relaxation made simple"; FIRE 2.0
// details from Guenole et al. 2020) on fictitious masses scaled to each particle's stiffness,
// so one time step suits the whole sheet however stiff the resin is next to the latex.
#include <functional>

#include "membra/model/model.hpp"
#include "membra/solve/solve_report.hpp"

namespace membra {

struct StaticOptions {
  double tolerance = 1e-6;   // converged when max |static force| <= tolerance x force_scale
  double force_scale = 1.0;  // N, normally k_stretch x grid spacing
  long max_iterations = 500000;
  int check_every = 25;  // iterations between convergence checks and progress calls
  // Wall-time budget (0: none), read after every iteration; stops unconverged when exceeded.
  double max_seconds = 0.0;
  bool uniform_mass = false;  // plain dynamic relaxation: one mass for all (the largest scaled
                              // one), as a baseline for the benchmarks
  std::function<void(const Progress&)> progress;
};

// FIRE relaxation that can be carried on in slices (the viewer advances it a little every frame),
// keeping its velocities, step and mixing between calls.
class StaticRelaxation {
 public:
  StaticRelaxation(const Model& model, const Points& x, const StaticOptions& options);
  // Starts afresh (masses from x, velocities zero, no forces kept): call it after the model
  // changed.
  void reset(const Model& model, const Points& x);
  // At most `iterations` more iterations (fewer when converged, diverged or out of
  // options.max_seconds); the report covers this call only. Velocities stay in the relaxation.
  SolveReport advance(const Model& model, State& state, long iterations);
  // The options it runs with (a caller may change the budget between calls).
  StaticOptions& options() { return options_; }
  // Iterations since the last reset.
  long iterations() const { return iterations_; }

 private:
  static constexpr double kAlphaStart = 0.25;
  // One FIRE iteration from the forces f at x (moves x and the velocities).
  void fire_step(const Model& model, Points& x, const Points& f, long it);
  StaticOptions options_;
  std::vector<double> mass_;
  Points v_;
  double dt_ = 0.1, alpha_ = kAlphaStart, size0_ = 1.0;
  int n_positive_ = 0;
  long iterations_ = 0;
  Points f_, x_of_f_;  // the forces the last advance() ended with, and where
};

// Moves the free particles of `state` to a nearby equilibrium (velocities are left zero).
// Never throws on divergence: the report says so.
SolveReport solve_static(const Model& model, State& state, const StaticOptions& options);

// Fictitious masses (N/m): a Gershgorin bound of each particle's stiffness from its springs and
// bending elements at positions x, so that the scaled system's frequencies are at most ~sqrt(2).
std::vector<double> stiffness_scaled_masses(const Model& model, const Points& x);

}  // namespace membra
