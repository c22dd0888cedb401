#include "membra/design/pattern_search.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include "membra/core/input_error.hpp"
#include "membra/core/stopwatch.hpp"
#include "membra/core/units.hpp"
#include "membra/design/dart_layout.hpp"
#include "membra/design/design_stretch.hpp"
#include "membra/design/resin_face.hpp"
#include "membra/design/stencil_trial.hpp"

namespace membra {
namespace {

using Evaluation = StencilTrial;

// The search's state: the forward simulations so far and the best of them.
class Search {
 public:
  Search(const DesignSpec& spec, DesignResult& r,
         const std::function<void(const DesignIteration&)>& progress)
      : spec_(spec),
        r_(r),
        progress_(progress),
        frame_{Vec2::Zero(), Vec2(spec.frame, spec.frame)} {
    if (spec_.layout.kind == "darts") make_dart_profiles();
    if (spec_.layout.kind == "fisheye_darts") {
      rows_ = row_profile(r.target, stretch_axis());
      if (spec_.lambda.minCoeff() > 1.0)
        r_.add_message(
            "Fisheye darts assume the latex stretched along one axis: with both stretched, the "
            "lenses shorten the columns too, which their widths do not allow for (use a "
            "\"lambda\" of 1 across).");
    }
  }

  // Darts of either kind: their scale is the search's parameter.
  bool darts() const { return spec_.layout.has_darts(); }

  bool out_of_budget() const { return n_ >= spec_.evaluations || clock_.seconds() >= spec_.budget; }
  int evaluations() const { return n_; }
  const DensityParameters& best_parameters() const { return best_d_; }

  // Simulates the stencil of density `d`; true when it is the best so far. A density whose
  // stencil was simulated already (a mean clamped at 0 or 1, steps too small to move a piece)
  // is not simulated again: it cannot be better.
  bool try_density(const DensityParameters& d) {
    const Stopwatch t;
    Stencil stencil = make_stencil(d);
    const Tried key{d.stretch, stencil.squares, hole_corners(stencil)};
    if (std::find(tried_.begin(), tried_.end(), key) != tried_.end()) return false;
    tried_.push_back(key);
    Evaluation e = simulate_stencil(with_stretch(spec_, d.stretch), r_.target, std::move(stencil));
    return record(d, std::move(e), t.seconds());
  }

  // Hands the best design to the result.
  void finish();

 private:
  bool record(const DensityParameters& d, Evaluation&& e, double seconds);
  Stencil make_stencil(const DensityParameters& d) const;
  void make_dart_profiles();
  std::vector<Vec2> found_centres();
  void note_frame_fit();

  const DesignSpec& spec_;
  DesignResult& r_;
  const std::function<void(const DesignIteration&)>& progress_;
  const Box2 frame_;
  const Stopwatch clock_;
  DensityParameters best_d_;
  Evaluation best_;
  bool best_converged_ = false;
  int n_ = 0;
  // The stencils simulated, by their stretch and pieces (squares, or the darts' corners: scales
  // that lay out the same darts, or none, are one stencil).
  using Tried = std::tuple<double, std::vector<StencilSquare>, std::vector<double>>;
  static std::vector<double> hole_corners(const Stencil& s) {
    std::vector<double> out;
    for (const PatternSpec* face : {&s.spec, &s.spec_bottom})  // either may hold the darts
      if (s.squares.empty() && face->kind == PatternSpec::Kind::difference)
        for (const PatternSpec& part : face->parts)
          for (const Vec2& p : part.points) out.insert(out.end(), {p.x(), p.y()});
    return out;
  }
  std::vector<Tried> tried_;
  std::vector<DartProfile> profiles_;  // darts: the target's deficit about each centre
  std::vector<Vec2> centres_;          // darts: their centres, when not the footprint's
  RowProfile rows_;                    // fisheye darts: the rows' latex shares
  int stretch_axis() const { return spec_.lambda.x() >= spec_.lambda.y() ? 0 : 1; }
};

// The target's deficit about each of the darts' centres. One centre, the footprint's, keeps
// lengths along the spokes from it, so its frame must fit the target (note_frame_fit); several
// must lie inside the footprint.
void Search::make_dart_profiles() {
  centres_ = spec_.layout.auto_centres ? found_centres() : spec_.layout.centres;
  if (centres_.empty()) {
    profiles_ = {dart_profile(r_.target)};
    note_frame_fit();
    return;
  }
  const Vec2 lo = r_.target.x.topRows<2>().rowwise().minCoeff();
  const Vec2 hi = r_.target.x.topRows<2>().rowwise().maxCoeff();
  for (size_t i = 0; i < centres_.size(); ++i) {
    const Vec2 c = centres_[i] + 0.5 * (lo + hi);
    // Rays from a centre on the rim would have no length towards it.
    const double m = 2.0 * spec_.layout.min_feature;
    const bool inside = r_.target.disk
                            ? (c - 0.5 * (lo + hi)).norm() < 0.5 * (hi - lo).minCoeff() - m
                            : ((c - lo).array() > m).all() && ((hi - c).array() > m).all();
    if (!inside) {
      const std::string where = "/resin/dart_centres/" + std::to_string(i);
      throw InputError(spec_.file.empty() ? where : spec_.file.string() + ": " + where,
                       "outside the target's footprint, or within twice min_feature of its rim "
                       "(mm from its centre)");
    }
    profiles_.push_back(dart_profile(r_.target, c));
  }
}

// `"dart_centres": "auto"`: the peaks of the target's Gaussian curvature, said in the message
// (none: the footprint's centre).
std::vector<Vec2> Search::found_centres() {
  const Vec2 size =
      r_.target.x.topRows<2>().rowwise().maxCoeff() - r_.target.x.topRows<2>().rowwise().minCoeff();
  std::vector<Vec2> peaks =
      curvature_peaks(r_.target, std::max(4.0 * spec_.layout.min_feature, 0.2 * size.minCoeff()));
  // Centres keep twice min_feature (and a little) from the rim, as written ones must.
  const double room = 0.5 * size.minCoeff() - 2.5 * spec_.layout.min_feature;
  std::erase_if(peaks, [&](const Vec2& p) {
    return r_.target.disk ? p.norm() > room : p.cwiseAbs().maxCoeff() > room;
  });
  if (peaks.empty()) {
    r_.add_message(
        "The target's Gaussian curvature has no peak that stands out: darts about its centre.");
    return peaks;
  }
  std::string text = "Darts about " + std::to_string(peaks.size()) +
                     " centres where the target's Gaussian curvature peaks (mm):";
  char point[64];
  for (const Vec2& p : peaks) {
    std::snprintf(point, sizeof point, " (%.0f, %.0f)", p.x() / units::mm, p.y() / units::mm);
    text += point;
  }
  r_.add_message(text + ".");
  return peaks;
}

// Darts keep lengths along the spokes: a frame as wide as the target measured along its surface
// makes the form at the target's size. Another frame makes it larger or smaller, which the
// alignment counts as error, so the design says which frame fits.
void Search::note_frame_fit() {
  const DartProfile& profile_ = profiles_.front();
  // The darts' width follows the circles' deficit: a target whose circles are, all round, nowhere
  // shorter than on a plane (a saddle) gets none.
  double most = -1.0;
  for (size_t i = 0; i < profile_.deficit[0].size(); ++i) {
    double mean = 0.0;
    for (const auto& ray : profile_.deficit) mean += ray[i] / profile_.rays;
    most = std::max(most, mean);
  }
  if (most <= 1e-9)
    r_.add_message(
        "The target's circles are nowhere shorter than on a plane: darts have no width here "
        "(they make domes; a saddle takes \"fisheye_darts\").");
  const double fit = 2.0 * profile_.radius;
  if (std::abs(spec_.frame - fit) <= 0.05 * fit) return;
  char text[200];
  std::snprintf(text, sizeof text,
                "Darts keep lengths from the centre: a frame %.0f mm across makes the target at "
                "its size (this one is %.0f mm).",
                fit / units::mm, spec_.frame / units::mm);
  r_.add_message(text);
}

Stencil Search::make_stencil(const DensityParameters& d) const {
  if (!darts())
    return design_stencil(spec_, r_.target, [&](const Vec2& p) { return d(p, frame_); });
  const Vec2 lambda = with_stretch(spec_, d.stretch).lambda;
  DartOptions o{spec_.layout.darts, d.darts, 0.0, spec_.layout.min_feature, {}, spec_.layout.cell};
  // A coat on the face the target bulges towards, cell by cell (the darts cut through both).
  if (spec_.resin_side == "convex")
    o.face = [&](const Vec2& p) {
      return convex_face(r_.target, frame_, p, 0.5 * spec_.layout.cell);
    };
  if (spec_.layout.kind == "fisheye_darts") {  // they shorten rows along the stretch
    o.lambda = lambda(rows_.axis);
    return layout_fisheye_darts(rows_, frame_, o);
  }
  // Darts shrink circles whichever way they run: the stretch's geometric mean sets by how much.
  o.lambda = std::sqrt(lambda.prod());
  return layout_darts(profiles_, frame_, r_.target.disk, o);
}

bool Search::record(const DensityParameters& d, Evaluation&& e, double seconds) {
  DesignIteration it = trial_iteration(e, n_++, seconds);
  it.parameters = d;
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
    r_.add_message(
        "No simulation reached equilibrium: the form shown is the last state of the best one, "
        "not a prediction (more iterations, or the static solver).");
  r_.best = best_d_;
  r_.spec = with_stretch(spec_, best_d_.stretch);  // its scene.json stretches as it was run
  r_.spec.layout.centres = centres_;               // found ones too (report.json)
  adopt_stencil(std::move(best_), r_);
}

// Buckled forms have many branches, and the start from mechanics may sit on a flat one (a sheet
// in tension stays flat): a few plain starts are tried too, and the search goes on from the best
// of them.
std::vector<DensityParameters> starts(const DensityParameters& start, bool darts) {
  // Darts: as wide as the metric asks, half as wide, and half as wide again (measured: the
  // cap's darts, held by the spokes, do best at 1.4; the saddle's fisheye darts near 0.5).
  if (darts) {
    std::vector<DensityParameters> out(3, start);
    out[1].darts = 0.5;
    out[2].darts = 1.5;
    return out;
  }
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
// `stretch`: the pre-stretch is a fourth parameter, its factor on the misfit bounded so that the
// most stretched direction stays between 1.05 and 2.5; `misfit` is that direction's lambda - 1.
// Darts have one parameter of their own, their scale (coordinate 4), besides the stretch.
void pattern_search(Search& search, bool stretch, double misfit) {
  std::array<double, 5> step = {0.15, 0.2, 0.2, 0.5, 0.25};
  constexpr double min_step = 0.02;
  std::vector<int> coordinates = search.darts() ? std::vector<int>{4} : std::vector<int>{0, 1, 2};
  if (stretch) coordinates.push_back(3);
  const size_t first = static_cast<size_t>(coordinates[0]);
  while (!search.out_of_budget() && step[first] >= min_step) {
    bool improved = false;
    for (int c : coordinates) {
      if (search.out_of_budget()) break;
      for (double sign : {+1.0, -1.0}) {
        if (search.out_of_budget()) break;
        DensityParameters d = search.best_parameters();
        double& v = c == 0   ? d.mean
                    : c == 1 ? d.radial
                    : c == 2 ? d.anisotropy
                    : c == 3 ? d.stretch
                             : d.darts;
        v += sign * step[static_cast<size_t>(c)];
        if (c == 0) v = std::clamp(v, 0.0, 1.0);
        if (c == 3) v = std::clamp(v, 0.05 / misfit, 1.5 / misfit);
        if (c == 4) v = std::clamp(v, 0.0, 4.0);
        if (search.try_density(d)) {
          improved = true;
          break;
        }
      }
    }
    if (!improved)
      for (double& s : step) s *= 0.5;
  }
}

}  // namespace

void design_by_pattern_search(const DesignSpec& spec, DesignResult& r,
                              const std::function<void(const DesignIteration&)>& progress) {
  r.method = "pattern_search";
  Search search(spec, r, progress);
  for (const DensityParameters& d : starts(r.start, search.darts())) {
    if (search.evaluations() > 0 && search.out_of_budget()) break;
    search.try_density(d);
  }
  pattern_search(search, spec.search_stretch, spec.lambda.maxCoeff() - 1.0);
  search.finish();
}

}  // namespace membra
