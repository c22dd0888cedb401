#include "membra/design/adjoint_design.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>

#include "membra/core/input_error.hpp"
#include "membra/core/stopwatch.hpp"
#include "membra/design/density_optimizer.hpp"
#include "membra/design/density_problem.hpp"
#include "membra/design/piece_map.hpp"
#include "membra/design/stencil_calibration.hpp"
#include "membra/design/stencil_trial.hpp"
#include "membra/design/target_correspondence.hpp"

namespace membra {
namespace {

// Stage 1's verdict per cell, in the result and its message.
void note_reach(const MetricStart& start, DesignResult& r) {
  r.unreachable_share = start.unreachable_share;
  r.asks_min = start.asks_min;
  r.asks_max = start.asks_max;
  if (start.unreachable_share <= 0.0) return;
  std::ostringstream why;
  why << "In " << std::lround(100.0 * start.unreachable_share)
      << " % of the cells the target asks for a resin density outside what the material can "
         "give (from "
      << start.asks_min << " to " << start.asks_max
      << ", where 0 is bare latex back at its natural size and 1 resin kept at its stretched "
         "size): "
      << (start.asks_max > 1.0 ? "more stretch than the frame gives there (a larger frame or "
                                 "pre-stretch, or a flatter target)"
                               : "more shrink than the latex gives there (more pre-stretch, or "
                                 "a larger target)")
      << ".";
  r.add_message(why.str());
}

DesignIteration density_iterate(const DensityIterate& it, double diameter,
                                const char* stage = "density") {
  DesignIteration d;
  d.index = it.index;
  d.stage = stage;
  d.rms_error = 100.0 * it.rms / diameter;
  d.objective = it.objective;
  d.gradient_norm = it.gradient_norm;
  d.seconds = it.seconds;
  d.best = it.best;
  if (!it.converged) {  // nothing measured: no numbers (null in report.json)
    d.note = "no stable equilibrium";
    d.rms_error = d.objective = d.gradient_norm = std::numeric_limits<double>::quiet_NaN();
  } else if (it.restarted) {
    d.note = "released again from the frame";
  }
  return d;
}

// The mean density, as the pattern search's parameters describe a design.
DensityParameters mean_only(const Eigen::VectorXd& rho) {
  DensityParameters p;
  p.mean = rho.mean();
  p.radial = p.anisotropy = 0.0;
  return p;
}

// The densities of stage 3's stencil trials, as multiples of the design's: the calibrated
// stencil first, then more and less resin. Which crumpled minimum a stencil of squares releases
// into changes with small changes of its pieces (docs/inverse_design.md), so a few neighbours
// of the calibrated stencil are simulated and the closest to the target is kept.
constexpr double kStencilScales[] = {1.0, 0.85, 1.15, 0.7, 1.3};

// A trial ranks above another when it is a prediction (settled) and the other is not, or both
// are alike and it is closer to the target.
bool better_trial(const StencilTrial& a, const StencilTrial& b) {
  if (a.note.empty() != b.note.empty()) return a.note.empty();
  return a.rms < b.rms;
}

Flattening flattening_of(const DesignSpec& spec) {
  return spec.flattening == "projection" ? Flattening::projection : Flattening::conformal;
}

// Every particle's point on the target through the design's flattening, the objective made
// dimensionless by the target's diameter: stage 2's and the piece sizing's target alike.
void aim_at_target(DensityProblem& problem, const DesignSpec& spec, const TargetSurface& target,
                   double smoothing) {
  problem.set_target(target_correspondence(target, problem.frame_positions(),
                                           problem.area_weights(), flattening_of(spec)),
                     target.diameter, smoothing);
}

// A trial that ended with a form whose error could be measured (not one that could not be
// simulated, or blew up): only such a trial can become the design.
bool simulated(const StencilTrial& t) {
  return t.run.prepared.membrane.state.x.cols() > 0 && std::isfinite(t.rms);
}

// The best trial's piece sizes optimised by the adjoint along the branch it released into
// (design/piece_map.hpp; warm-started from its form, so the crumpled minimum it found is
// followed, not another). Nothing when no size did better; else the sized stencil and the note
// saying how close its branch came.
struct SizedStencil {
  Stencil stencil;
  std::string note;
};
std::optional<SizedStencil> size_pieces(
    const DesignSpec& spec, const Scene& scene, const StencilTrial& best, DesignResult& r,
    double seconds, const std::function<void(const DesignIteration&)>& progress) {
  const PieceMap* map = nullptr;
  DensityProblem problem(scene, [&](const Membrane& m, const Points& frame_x) {
    auto made = std::make_unique<PieceMap>(best.stencil, spec.layout.min_feature, m, frame_x);
    map = made.get();
    return made;
  });
  if (map->size() == 0) return {};  // only filled cells: nothing to size
  aim_at_target(problem, spec, r.target, 0.0);
  const Eigen::VectorXd start = map->variables();
  if (!problem.solve_from(start, best.run.prepared.membrane.state.x)) return {};
  problem.keep_to_branch();
  DensityOptimizerOptions o;
  o.evaluations = spec.piece_evaluations;
  o.max_seconds = seconds;
  o.relative_change = 1e-6;
  const int first = static_cast<int>(r.history.size());
  const DensityOptimum sized = optimize_density(problem, start, o, [&](const DensityIterate& it) {
    r.history.push_back(density_iterate(it, r.target.diameter, "pieces"));
    r.history.back().index = first + it.index;
    if (progress) progress(r.history.back());
  });
  if (sized.rho == start) return {};
  // How close the branch itself came, by the same measure as every stencil's error: whether a
  // release from flat keeps it is what the next run says.
  std::ostringstream note;
  note << "piece sizes refined";
  if (problem.solve(sized.rho)) {
    const Membrane& m = problem.membrane();
    note << " (on the branch: "
         << 100.0 * compare_shapes(problem.positions(), m.sheet.triangles, r.target).rms /
                r.target.diameter
         << " %)";
  }
  return SizedStencil{map->stencil(sized.rho), note.str()};
}

// Stage 3's last step: the best trial's pieces sized (size_pieces), then released from flat as
// `membra run` would; kept when that run is the closer to the target.
void refine_pieces(const DesignSpec& spec, const Scene& scene, StencilTrial& best,
                   const DesignIteration& trial, DesignResult& r, const Stopwatch& clock,
                   double deadline, const std::function<void(const DesignIteration&)>& progress) {
  // The sized stencil's run from flat takes about as long as the trial's: it is kept out of the
  // sizing's time, so that the design ends within its budget.
  const double seconds = deadline - clock.seconds() - trial.seconds;
  if (spec.piece_evaluations <= 0 || best.stencil.squares.empty() || !best.note.empty() ||
      seconds <= 0.0)
    return;
  std::optional<SizedStencil> sized = size_pieces(spec, scene, best, r, seconds, progress);
  if (!sized) return;
  const double began = clock.seconds();
  StencilTrial t = simulate_stencil(spec, r.target, std::move(sized->stencil));
  r.history.push_back(
      trial_iteration(t, static_cast<int>(r.history.size()), clock.seconds() - began));
  DesignIteration& it = r.history.back();
  it.scale = trial.scale;  // the densities' multiple of the trial it was sized from
  it.note = t.note.empty() ? sized->note : sized->note + ", " + t.note;
  if (simulated(t) && better_trial(t, best)) {
    it.best = true;
    best = std::move(t);
  }
  if (progress) progress(it);
}

// Stage 3: squares whose measured effect is the wanted density (design/stencil_calibration.hpp),
// simulated from the flat start, then (spec.stencil_trials) the same with the densities scaled;
// the best trial becomes the design's result. `deadline`: seconds of `clock` after which no
// further trial starts.
void lay_out_and_simulate(const DesignSpec& spec, const Scene& scene, DesignResult& r,
                          const Stopwatch& clock, double deadline,
                          const std::function<void(const DesignIteration&)>& progress) {
  const TargetSurface& target = r.target;
  const StencilCalibration calibration = calibrate_stencil(spec);
  r.calibration_share = calibration.share;
  r.calibration_density = calibration.density;
  r.calibration_cached = calibration.cached;
  std::optional<StencilTrial> best;
  DesignIteration best_trial;
  const int trials =
      std::clamp(spec.stencil_trials, 1, static_cast<int>(std::size(kStencilScales)));
  for (int k = 0; k < trials && (k == 0 || clock.seconds() < deadline); ++k) {
    const double scale = kStencilScales[k];
    const double start = clock.seconds();
    StencilTrial t = try_stencil(spec, target, [&](const Vec2& p) {
      return calibration.share_for(std::clamp(scale * r.density.at(p), 0.0, 1.0));
    });
    r.history.push_back(
        trial_iteration(t, static_cast<int>(r.history.size()), clock.seconds() - start));
    r.history.back().scale = scale;
    const bool settled_form = simulated(t);
    if (settled_form && (!best || better_trial(t, *best))) {
      r.history.back().best = true;
      best = std::move(t);
      best_trial = r.history.back();
    }
    if (progress) progress(r.history.back());
    if (k == 0 && !settled_form)
      throw InputError(spec.file.string(),
                       "the designed stencil could not be simulated: " + t.note);
  }
  refine_pieces(spec, scene, *best, best_trial, r, clock, deadline, progress);
  if (!best->note.empty())
    r.add_message("The stencil's simulation " + best->note +
                  ": the form shown is its last state, not a prediction.");
  adopt_stencil(std::move(*best), r);
}

}  // namespace

void design_by_adjoint(const DesignSpec& spec, DesignResult& r,
                       const std::function<void(const DesignIteration&)>& progress) {
  const Stopwatch clock;
  r.method = "adjoint";
  // Newton to a tight tolerance: the adjoint needs the equilibrium's Hessian, and gradients are
  // only as exact as the equilibria.
  Scene scene = spec.scene;
  scene.simulation.solver = Solver::newton;
  scene.simulation.tolerance = std::min(scene.simulation.tolerance, 1e-8);
  const Box2 frame{Vec2::Zero(), Vec2(spec.frame, spec.frame)};
  DensityProblem problem(scene, make_density_field(frame, spec.density_cell, 0.5));
  const TargetSurface& target = r.target;
  aim_at_target(problem, spec, target, spec.smoothing);
  const MetricStart start = metric_start(target, problem.frame_positions(), problem.field(),
                                         spec.lambda, flattening_of(spec));
  note_reach(start, r);

  DensityOptimizerOptions o;
  o.evaluations = spec.evaluations;
  o.max_seconds = 0.8 * spec.budget;  // the rest for the calibration and the stencil's run
  // A flat or symmetric start has a tiny gradient, and the first steps change the objective by
  // little: only the evaluation budget (or steps that no longer move the densities) ends it.
  o.relative_change = 0.0;
  const DensityOptimum best =
      optimize_density(problem, start.density, o, [&](const DensityIterate& it) {
        r.history.push_back(density_iterate(it, target.diameter));
        if (progress) progress(r.history.back());
      });
  r.stopped = best.stopped;
  r.density = problem.field();
  r.density.value = best.rho;
  r.start = mean_only(start.density);
  r.best = mean_only(best.rho);
  if (problem.solve(best.rho)) {
    r.density_form = problem.positions();
    r.density_error = compare_shapes(r.density_form, problem.membrane().sheet.triangles, target);
    r.density_rms_error = 100.0 * r.density_error.rms / target.diameter;
  }

  lay_out_and_simulate(spec, scene, r, clock, spec.budget, progress);
}

}  // namespace membra
