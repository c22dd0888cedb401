#include "membra/design/inverse_design.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

#include "membra/core/input_error.hpp"
#include "membra/core/units.hpp"
#include "membra/design/adjoint_design.hpp"
#include "membra/measure/curvature.hpp"

namespace membra {
namespace {

// Area of the natural sheet (square, or the disk inscribed in it).
double natural_area(const DesignSpec& s, bool disk) {
  const double wx = s.frame / s.lambda.x(), wy = s.frame / s.lambda.y();
  return disk ? 0.25 * std::acos(-1.0) * wx * wy : wx * wy;
}

using Evaluation = StencilTrial;

}  // namespace

double DensityParameters::operator()(const Vec2& p, const Box2& frame) const {
  const Vec2 c = 0.5 * (frame.min + frame.max), h = 0.5 * (frame.max - frame.min);
  const double u = (p.x() - c.x()) / h.x(), v = (p.y() - c.y()) / h.y();
  // r^2 - 1/2 and x^2 - y^2 average to about zero over the frame: the mean stays the mean.
  return mean + radial * (u * u + v * v - 0.5) + anisotropy * (u * u - v * v);
}

Scene stencil_scene(const DesignSpec& spec, const Stencil& stencil) {
  Scene scene = spec.scene;
  if (stencil.pattern) {
    auto& resin = std::get<ImpregnateStep>(scene.protocol[1].step);
    resin.pattern = stencil.pattern;
    resin.pattern_spec = stencil.spec;
  } else {
    // No resin: stretch and release only, numbered as the scene file numbers them.
    scene.protocol.erase(scene.protocol.begin() + 1);
    scene.protocol[1].pointer = "/protocol/1";
  }
  return scene;
}

namespace {

// Where to start, from mechanics, and whether the target can be reached at all. Resin keeps the
// stretched size, latex returns to its natural size: the released area lies between the natural
// and the frame's, roughly in proportion to the resin's share. And a metric with Gaussian
// curvature K needs the scale to fall off as -K r^2 / 4 from the centre (Liouville's equation for
// small K r^2): more resin in the middle for a dome (K > 0), at the rim for a saddle (K < 0).
void start_from_mechanics(const DesignSpec& spec, DesignResult& r) {
  const TargetSurface& target = r.target;
  const double a_nat = natural_area(spec, target.disk), a_frame = a_nat * spec.lambda.prod();
  const double share = (target.area - a_nat) / (a_frame - a_nat);
  std::ostringstream why;
  if (share > 1.02) {
    why << "the target's area (" << target.area / (units::mm * units::mm)
        << " mm^2) is more than the stretched frame's (" << a_frame / (units::mm * units::mm)
        << " mm^2): resin keeps the stretched size and latex shrinks, so the released sheet is "
           "never larger than the frame. Use a larger frame or pre-stretch, or a smaller target.";
  } else if (share < -0.02) {
    why << "the target's area (" << target.area / (units::mm * units::mm)
        << " mm^2) is less than the natural sheet's (" << a_nat / (units::mm * units::mm)
        << " mm^2): the latex cannot shrink below its natural size. Use less pre-stretch or a "
           "larger target.";
  }
  r.reachable = why.str().empty();
  r.message = why.str();
  // What a flat sheet of the target's footprint scores: a design is only worth its error below
  // this.
  Points flat = target.x;
  flat.row(2).setZero();
  r.flat_error = 100.0 * compare_shapes(flat, target.triangles, target).rms / target.diameter;
  const GaussianCurvature k = gaussian_curvature(target.x, target.triangles);
  const double k_mean = k.total / target.area;
  const double half = 0.5 * std::sqrt(a_nat);
  const double lam = std::sqrt(spec.lambda.prod());
  r.start.mean = std::clamp(share, 0.0, 1.0);
  r.start.radial = std::clamp(-k_mean * half * half / (4.0 * (1.0 - 1.0 / lam)), -1.0, 1.0);
  r.start.anisotropy = 0.0;
}

// The search's state: the forward simulations so far and the best of them.
class Search {
 public:
  Search(const DesignSpec& spec, DesignResult& r,
         const std::function<void(const DesignIteration&)>& progress)
      : spec_(spec),
        r_(r),
        progress_(progress),
        frame_{Vec2::Zero(), Vec2(spec.frame, spec.frame)} {}

  bool out_of_budget() const { return n_ >= spec_.evaluations || clock_.seconds() >= spec_.budget; }
  int evaluations() const { return n_; }
  const DensityParameters& best_parameters() const { return best_d_; }

  // Simulates the stencil of density `d`; true when it is the best so far.
  bool try_density(const DensityParameters& d) {
    const Stopwatch t;
    Evaluation e = evaluate(d);
    return record(d, std::move(e), t.seconds());
  }

  // Hands the best design to the result.
  void finish();

 private:
  Evaluation evaluate(const DensityParameters& d) const;
  bool record(const DensityParameters& d, Evaluation&& e, double seconds);

  const DesignSpec& spec_;
  DesignResult& r_;
  const std::function<void(const DesignIteration&)>& progress_;
  const Box2 frame_;
  const Stopwatch clock_;
  DensityParameters best_d_;
  Evaluation best_;
  bool best_converged_ = false;
  int n_ = 0;
};

Evaluation Search::evaluate(const DensityParameters& d) const {
  return try_stencil(spec_, r_.target, [&](const Vec2& p) { return d(p, frame_); });
}

bool Search::record(const DensityParameters& d, Evaluation&& e, double seconds) {
  DesignIteration it;
  it.index = n_++;
  it.parameters = d;
  it.rms_error = e.rms;
  it.max_error = e.max;
  it.resin_share = e.stencil.resin_share;
  it.pieces = e.stencil.pieces;
  it.seconds = seconds;
  it.note = e.note;
  // Only an equilibrium is a prediction: an unconverged state competes only while no converged
  // one exists.
  const bool converged = e.note.empty();
  it.best = (converged && (!best_converged_ || e.rms < best_.rms)) ||
            (!converged && !best_converged_ && e.rms < best_.rms);
  if (it.best) {
    best_ = std::move(e);
    best_d_ = d;
    best_converged_ = converged;
  }
  r_.history.push_back(it);
  if (progress_) progress_(it);
  return it.best;
}

void Search::finish() {
  if (best_.run.prepared.membrane.state.x.cols() == 0)
    throw InputError(spec_.file.string(), "no stencil could be simulated: " +
                                              (r_.history.empty() ? std::string("no evaluation")
                                                                  : r_.history.back().note));
  if (!best_converged_)
    r_.message += std::string(r_.message.empty() ? "" : " ") +
                  "No simulation reached equilibrium: the form shown is the last state of the "
                  "best one, not a prediction (more iterations, or the static solver).";
  r_.best = best_d_;
  adopt_stencil(std::move(best_), r_);
}

// Buckled forms have many branches, and the start from mechanics may sit on a flat one (a sheet
// in tension stays flat): a few plain starts are tried too, and the search goes on from the best
// of them.
std::vector<DensityParameters> starts(const DensityParameters& start) {
  std::vector<DensityParameters> out = {start};
  for (double mean : {start.mean, start.mean - 0.25, start.mean + 0.25}) {
    DensityParameters d;
    d.mean = std::clamp(mean, 0.0, 1.0);
    d.radial = d.anisotropy = 0.0;
    if (std::none_of(out.begin(), out.end(), [&](const DensityParameters& o) {
          return o.mean == d.mean && o.radial == d.radial && o.anisotropy == d.anisotropy;
        }))
      out.push_back(d);
  }
  return out;
}

// Pattern search (Hooke and Jeeves without the pattern move): try each parameter up and down by
// its step, keep any improvement, halve the steps when none helps.
void pattern_search(Search& search) {
  std::array<double, 3> step = {0.15, 0.2, 0.2};
  constexpr double min_step = 0.02;
  while (!search.out_of_budget() && step[0] >= min_step) {
    bool improved = false;
    for (int c = 0; c < 3 && !search.out_of_budget(); ++c)
      for (double sign : {+1.0, -1.0}) {
        if (search.out_of_budget()) break;
        DensityParameters d = search.best_parameters();
        double& v = c == 0 ? d.mean : c == 1 ? d.radial : d.anisotropy;
        v += sign * step[static_cast<size_t>(c)];
        if (c == 0) v = std::clamp(v, 0.0, 1.0);
        if (search.try_density(d)) {
          improved = true;
          break;
        }
      }
    if (!improved)
      for (double& s : step) s *= 0.5;
  }
}

}  // namespace

StencilTrial try_stencil(const DesignSpec& spec, const TargetSurface& target,
                         const std::function<double(const Vec2&)>& density) {
  StencilTrial e;
  const Box2 frame{Vec2::Zero(), Vec2(spec.frame, spec.frame)};
  const Vec2 centre = 0.5 * frame.max;
  const auto inside = [&](const Vec2& p) {
    return !target.disk || (p - centre).norm() <= 0.5 * spec.frame;
  };
  e.stencil = layout_stencil(density, frame, spec.layout, inside);
  e.scene = stencil_scene(spec, e.stencil);
  try {
    e.run = run_scene(e.scene);
  } catch (const InputError& err) {
    // E.g. squares so small on a coarse grid that they cover no spring: not a form.
    e.note = std::string("not simulated: ") + err.what();
    return e;
  }
  if (e.run.solve.diverged) {
    e.note = "diverged";
    return e;
  }
  if (!e.run.solve.converged) e.note = "did not converge";
  const Membrane& m = e.run.prepared.membrane;
  e.error = compare_shapes(m.state.x, m.sheet.triangles, target);
  e.rms = 100.0 * e.error.rms / target.diameter;
  e.max = 100.0 * e.error.max / target.diameter;
  return e;
}

void adopt_stencil(StencilTrial&& trial, DesignResult& r) {
  r.scene = std::move(trial.scene);
  r.stencil = std::move(trial.stencil);
  r.run = std::move(trial.run);
  r.error = std::move(trial.error);
  r.rms_error = trial.rms;
  r.max_error = trial.max;
}

DesignResult run_design(const DesignSpec& spec,
                        const std::function<void(const DesignIteration&)>& progress) {
  const Stopwatch clock;
  DesignResult r;
  r.spec = spec;
  r.target = make_target(spec.target);
  start_from_mechanics(spec, r);
  if (spec.method == "adjoint") {
    design_by_adjoint(spec, r, progress);
    r.seconds = clock.seconds();
    return r;
  }
  r.method = "pattern_search";
  Search search(spec, r, progress);
  for (const DensityParameters& d : starts(r.start)) {
    if (search.evaluations() > 0 && search.out_of_budget()) break;
    search.try_density(d);
  }
  pattern_search(search);
  search.finish();
  r.seconds = clock.seconds();
  return r;
}

}  // namespace membra
