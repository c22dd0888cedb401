#include "membra/design/density_optimizer.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>

#include <nlopt.hpp>

#include "membra/core/stopwatch.hpp"

namespace membra {
namespace {

struct Run {
  DensityProblem& problem;
  const std::function<void(const DensityIterate&)>& progress;
  Stopwatch clock;
  DensityOptimum best;
  double worst = 0.0;  // the largest objective seen: a failed equilibrium counts as worse
  double scale = 1.0;  // what the optimiser sees: objective x scale (its gradient likewise)

  double operator()(const std::vector<double>& v, std::vector<double>& grad) {
    const Eigen::VectorXd rho =
        Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
    const DensityEvaluation ev = problem.evaluate(rho);
    DensityIterate it;
    it.index = static_cast<int>(best.history.size());
    it.converged = ev.converged;
    it.restarted = ev.restarted;
    it.newton_iterations = ev.newton_iterations;
    it.seconds = clock.seconds();
    double value = ev.objective;
    if (ev.converged) {
      it.objective = ev.objective;
      it.rms = std::sqrt(ev.distance);
      it.gradient_norm = ev.gradient.norm();
      worst = std::max(worst, ev.objective);
      if (best.rho.size() == 0 || ev.objective < best.objective) {
        best.rho = rho;
        best.objective = ev.objective;
        best.rms = it.rms;
        it.best = true;
        problem.anchor();
      }
    } else {
      value = 10.0 * worst + 1.0;
    }
    if (!grad.empty()) Eigen::Map<Eigen::VectorXd>(grad.data(), rho.size()) = scale * ev.gradient;
    best.history.push_back(it);
    if (progress) progress(it);
    return scale * value;
  }
};

const char* reason(nlopt::result r) {
  switch (r) {
    case nlopt::SUCCESS:
      return "converged";
    case nlopt::STOPVAL_REACHED:
      return "reached the target value";
    case nlopt::FTOL_REACHED:
      return "the objective stopped changing";
    case nlopt::XTOL_REACHED:
      return "the densities stopped changing";
    case nlopt::MAXEVAL_REACHED:
      return "used every evaluation";
    case nlopt::MAXTIME_REACHED:
      return "used the time budget";
    default:
      return "stopped";
  }
}

}  // namespace

DensityOptimum optimize_density(DensityProblem& problem, const Eigen::VectorXd& start,
                                const DensityOptimizerOptions& options,
                                const std::function<void(const DensityIterate&)>& progress) {
  const auto n = static_cast<unsigned>(start.size());
  if (n == 0) throw std::invalid_argument("no design variables");
  Run run{problem, progress, Stopwatch{}, {}, 0.0, 1.0};
  // The optimiser's own tests are absolute: scale the objective so that the start's gradient is
  // of order one (a nearly flat, symmetric start has a gradient of 1e-6 and L-BFGS stopped there
  // at once, "converged").
  const DensityEvaluation first = problem.evaluate(start.cwiseMax(0.0).cwiseMin(1.0));
  if (first.converged && first.gradient.cwiseAbs().maxCoeff() > 0.0)
    run.scale = 1.0 / first.gradient.cwiseAbs().maxCoeff();
  nlopt::opt opt(nlopt::LD_LBFGS, n);
  opt.set_lower_bounds(0.0);
  opt.set_upper_bounds(1.0);
  opt.set_maxeval(std::max(1, options.evaluations));
  if (options.max_seconds > 0.0) opt.set_maxtime(options.max_seconds);
  if (options.relative_change > 0.0) opt.set_ftol_rel(options.relative_change);
  opt.set_xtol_rel(1e-8);
  // An exception in an evaluation (a requested stop, bad input) ends the optimisation and is
  // rethrown as it was, not as NLopt's own.
  std::exception_ptr failure;
  struct Context {
    Run* run;
    nlopt::opt* opt;
    std::exception_ptr* failure;
  } context{&run, &opt, &failure};
  opt.set_min_objective(
      [](const std::vector<double>& x, std::vector<double>& g, void* data) {
        auto* c = static_cast<Context*>(data);
        try {
          return (*c->run)(x, g);
        } catch (...) {
          *c->failure = std::current_exception();
          c->opt->force_stop();
          return std::numeric_limits<double>::quiet_NaN();
        }
      },
      &context);
  std::vector<double> x(start.data(), start.data() + start.size());
  for (double& v : x) v = std::clamp(v, 0.0, 1.0);
  double value = 0.0;
  try {
    run.best.stopped = reason(opt.optimize(x, value));
  } catch (const std::exception& e) {  // NLopt throws on a failed line search ("roundoff")
    run.best.stopped = std::string("stopped: ") + e.what();
  }
  if (failure) std::rethrow_exception(failure);
  if (run.best.rho.size() == 0) run.best.rho = start;
  return run.best;
}

}  // namespace membra
