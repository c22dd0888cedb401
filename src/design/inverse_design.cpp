#include "membra/design/inverse_design.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "membra/core/stopwatch.hpp"
#include "membra/core/units.hpp"
#include "membra/design/adjoint_design.hpp"
#include "membra/design/pattern_search.hpp"
#include "membra/measure/curvature.hpp"

namespace membra {
namespace {

// Area of the natural sheet (square, or the disk inscribed in it).
double natural_area(const DesignSpec& s, bool disk) {
  const double wx = s.frame / s.lambda.x(), wy = s.frame / s.lambda.y();
  return disk ? 0.25 * std::acos(-1.0) * wx * wy : wx * wy;
}

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

}  // namespace

DesignResult run_design(const DesignSpec& spec,
                        const std::function<void(const DesignIteration&)>& progress) {
  const Stopwatch clock;
  DesignResult r;
  r.spec = spec;
  r.target = make_target(spec.target);
  start_from_mechanics(spec, r);
  if (spec.method == "adjoint")
    design_by_adjoint(spec, r, progress);
  else
    design_by_pattern_search(spec, r, progress);
  r.seconds = clock.seconds();
  return r;
}

}  // namespace membra
