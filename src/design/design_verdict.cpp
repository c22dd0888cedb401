#include "membra/design/design_verdict.hpp"

#include <cmath>
#include <ostream>
#include <sstream>
#include <string>

#include "membra/design/design_result.hpp"
#include "membra/measure/curvature.hpp"

namespace membra {
namespace {

// The goal (docs/inverse_design.md): within 2 % of the target's diameter and at most
// half of a flat sheet's error.
constexpr double kGoalRms = 2.0, kGoalOfFlat = 0.5;
// Neighbouring stencils' crumpled releases often differ by more than a tenth of a flat sheet's
// error, so a smaller margin than this says little about shape.
constexpr double kClearlyCloser = 0.9;
// The goal is set on sheets this fine or finer: coarser ones release some stencils into other
// forms (the pattern search's cap: 1.8 % at 17^2, 4.9 % at 33^2).
constexpr int kGoalResolution = 33;

// Why a stencil's form is no prediction, or "" when it is one: settled (run_result.hpp's one
// definition of an end state worth keeping) with a finite error. Only the words are decided here.
std::string unsettled_reason(const DesignResult& r) {
  const RunResult& run = r.run;
  if (settled(run)) return std::isfinite(r.rms_error) ? "" : "has no measurable form";
  if (run.out_of_time) return "ran out of its time";
  if (!run.solve.converged || run.solve.diverged) return "ended unconverged";
  return "ended at a saddle point, not a minimum";
}

// The grade and its first clause: the errors against the goal and a flat sheet.
void grade(const DesignResult& r, DesignVerdict& v, std::ostream& s) {
  const std::string unsettled = unsettled_reason(r);
  if (unsettled.empty() && r.rms_error <= kGoalRms && r.rms_error <= kGoalOfFlat * r.flat_error) {
    v.grade = "meets_goal";
    s << "the stencil's form meets the goal: " << r.rms_error << " % of the target's diameter "
      << "(at most 2 % and at most half a flat sheet's " << r.flat_error << " %)";
    if (r.spec.resolution < kGoalResolution)
      s << ", on a " << r.spec.resolution << " x " << r.spec.resolution << " sheet (check it on "
        << kGoalResolution << " x " << kGoalResolution
        << " or finer: a coarse sheet can release a stencil into another form)";
  } else if (unsettled.empty() && r.rms_error <= kClearlyCloser * r.flat_error) {
    v.grade = "closer_than_flat";
    s << "the stencil's form comes closer than a flat sheet (" << r.rms_error << " against "
      << r.flat_error << " %) but falls short of the goal (at most 2 % and half a flat sheet's)";
  } else {
    v.grade = "no_closer_than_flat";
    s << "the stencil does not make the target's form: ";
    if (unsettled.empty())
      s << "its error is not clearly smaller than a flat sheet's (" << r.rms_error << " against "
        << r.flat_error << " %)";
    else
      s << "its simulation " << unsettled << ", so its form is no prediction";
  }
}

// A target that bends far more than its Gaussian curvature says (a cylinder, a wave): integrated
// |K| below a fifth of integrated H^2 over the interior (a sphere: 1, a cylinder: 0). The
// in-plane shrink a density makes bends a sheet only through K; a coat on one face bends it
// directly.
bool mostly_bent(const TargetSurface& t) {
  if (t.triangles.empty()) return false;
  const GaussianCurvature k = gaussian_curvature(t.x, t.triangles);
  const std::vector<double> h = mean_curvature(t.x, t.triangles);
  double h2 = 0.0;
  for (size_t i = 0; i < h.size(); ++i)
    if (k.interior[i]) h2 += h[i] * h[i] * k.area[i];
  return h2 > 0.0 && k.positive - k.negative < 0.2 * h2;
}

// +1 for a dome, -1 for a saddle: nearly all of the target's Gaussian curvature of one sign
// (over 0.9 of the integrated |K|), which darts make (dart_layout.hpp); else 0.
int dome_or_saddle(const TargetSurface& t) {
  if (t.triangles.empty()) return 0;
  const GaussianCurvature k = gaussian_curvature(t.x, t.triangles);
  const double all = k.positive - k.negative;
  if (all <= 0.0) return 0;
  return k.positive > 0.9 * all ? +1 : -k.negative > 0.9 * all ? -1 : 0;
}

}  // namespace

DesignVerdict design_verdict(const DesignResult& r) {
  DesignVerdict v;
  std::ostringstream s;
  s.precision(3);
  grade(r, v, s);
  if (r.stencil.pieces == 0) s << "; the stencil has no resin at all: its form is the bare sheet's";
  if (!r.reachable) {
    s << "; the target is out of reach (design.message says why)";
  } else if (v.grade != "meets_goal" && std::isfinite(r.density_rms_error) &&
             !(std::isfinite(r.rms_error) && r.density_rms_error >= r.rms_error)) {
    s << "; the density design (density.png) releases to within " << r.density_rms_error
      << " % of the target, and the stencil of squares does not keep that form";
  } else if (v.grade != "meets_goal" && !r.spec.bilayer && mostly_bent(r.target)) {
    s << "; the target bends with little Gaussian curvature (like a cylinder or a wave), which a "
         "shrink in the plane does not make and a coat on one face does: try \"resin\": "
         "{\"bilayer\": true} with the frame stretched across its ridges (and \"resin_side\": "
         "\"convex\" where it bends both ways)";
  } else if (v.grade != "meets_goal" && r.spec.layout.has_darts()) {
    s << "; darts follow the target's metric alone: try another number of darts, a finer sheet, "
         "or a frame as wide as the target measured along its surface";
    // A coat chooses which way each part bulges and bends where the metric does not.
    if (!r.spec.bilayer)
      s << "; where it bulges both ways or bends, cut them through a coat: \"bilayer\": true, "
           "\"resin_side\": \"convex\"";
  } else if (const int kind =
                 v.grade != "meets_goal" && !r.spec.bilayer ? dome_or_saddle(r.target) : 0;
             kind > 0) {
    s << "; the target is a dome, which darts make: try \"resin\": {\"layout\": \"darts\"} "
         "with a frame as wide as the target measured along its surface";
  } else if (kind < 0) {
    s << "; the target is a saddle, which fisheye darts make: try \"resin\": {\"layout\": "
         "\"fisheye_darts\"} with the frame stretched along one axis (\"lambda\": [1.1, 1])";
  } else if (v.grade != "meets_goal" && r.method != "adjoint" && !r.spec.bilayer) {
    s << "; try \"method\": \"adjoint\", which designs a density per cell";
  }
  v.sentence = s.str();
  return v;
}

}  // namespace membra
