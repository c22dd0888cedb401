#include "membra/design/design_verdict.hpp"

#include <cmath>
#include <sstream>

#include "membra/design/design_result.hpp"

namespace membra {
namespace {

// The goal (docs/inverse_design.md): within 2 % of the target's diameter and at most
// half of a flat sheet's error.
constexpr double kGoalRms = 2.0, kGoalOfFlat = 0.5;
// Neighbouring stencils' crumpled releases differ by more than a tenth of a flat sheet's error,
// so a smaller margin than this says nothing about shape.
constexpr double kClearlyCloser = 0.9;
// The goal is set on sheets this fine or finer: coarser ones release some stencils into other
// forms (the pattern search's cap: 1.8 % at 17^2, 4.9 % at 33^2).
constexpr int kGoalResolution = 33;

}  // namespace

DesignVerdict design_verdict(const DesignResult& r) {
  DesignVerdict v;
  std::ostringstream s;
  s.precision(3);
  const bool measured = std::isfinite(r.rms_error) && settled(r.run);
  if (measured && r.rms_error <= kGoalRms && r.rms_error <= kGoalOfFlat * r.flat_error) {
    v.grade = "meets_goal";
    s << "the stencil's form meets the goal: " << r.rms_error << " % of the target's diameter ("
      << "at most 2 %), a flat sheet " << r.flat_error << " %";
    if (r.spec.resolution < kGoalResolution)
      s << ", on a " << r.spec.resolution << " x " << r.spec.resolution << " sheet (check it on "
        << kGoalResolution << " x " << kGoalResolution
        << " or finer: a coarse sheet can release a stencil into another form)";
  } else if (measured && r.rms_error <= kClearlyCloser * r.flat_error) {
    v.grade = "closer_than_flat";
    s << "the stencil's form comes closer than a flat sheet (" << r.rms_error << " against "
      << r.flat_error << " %) but short of the goal (at most 2 % and half a flat sheet's)";
  } else {
    v.grade = "no_closer_than_flat";
    s << "the stencil does not make the target's form: "
      << (measured ? "its error is not clearly smaller than a flat sheet's ("
                   : "it reached no equilibrium (")
      << r.rms_error << " against " << r.flat_error << " %)";
    if (r.stencil.pieces == 0) s << "; the best stencil has no resin at all";
  }
  if (v.grade != "meets_goal" && std::isfinite(r.density_rms_error))
    s << "; the density design (density.png) releases within " << r.density_rms_error
      << " %, the stencil of squares does not keep it";
  else if (v.grade != "meets_goal" && r.method != "adjoint")
    s << "; try \"method\": \"adjoint\", which designs a density per cell";
  v.sentence = s.str();
  return v;
}

}  // namespace membra
