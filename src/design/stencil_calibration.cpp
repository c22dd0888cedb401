#include "membra/design/stencil_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "membra/design/density_problem.hpp"
#include "membra/design/stencil_trial.hpp"
#include "membra/design/target_surface.hpp"

namespace membra {
namespace {

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double v) {
  if (v <= x.front()) return y.front();
  if (v >= x.back()) return y.back();
  const auto it = std::upper_bound(x.begin(), x.end(), v);
  const size_t k = static_cast<size_t>(it - x.begin());
  const double t = (v - x[k - 1]) / (x[k] - x[k - 1]);
  return y[k - 1] + t * (y[k] - y[k - 1]);
}

// The released area of a uniform density, on a grid of densities (flat, cheap solves).
struct AreaCurve {
  std::vector<double> rho, area;
};
AreaCurve area_curve(const DesignSpec& spec, const Scene& scene) {
  AreaCurve c;
  const Box2 frame{Vec2::Zero(), Vec2(spec.frame, spec.frame)};
  DensityProblem problem(scene, make_density_field(frame, 0.5 * spec.frame, 0.0));
  for (int k = 0; k <= 10; ++k) {
    const double rho = 0.1 * k;
    if (!problem.solve(Eigen::VectorXd::Constant(problem.field().value.size(), rho)))
      throw std::runtime_error("the calibration's uniform sheet found no equilibrium");
    c.rho.push_back(rho);
    c.area.push_back(mesh_area(problem.positions(), problem.membrane().sheet.triangles));
    // The inverse below needs the area to grow with the density (resin keeps the stretched size).
    if (k > 0 && !(c.area[k] > c.area[k - 1]))
      throw std::runtime_error("the calibration's uniform sheet did not grow with its density");
  }
  return c;
}

// The calibration as membra measures it: the uniform density's area curve, then each sample
// square's uniform stencil released and read off that curve.
StencilCalibration measure_calibration(const DesignSpec& spec, int samples,
                                       const std::function<void(double, double)>& progress) {
  Scene scene = spec.scene;
  scene.simulation.solver = Solver::newton;
  const AreaCurve curve = area_curve(spec, scene);
  // The cell as layout_stencil lays it (a whole number of cells across the frame).
  const double cell = spec.frame / std::max(1.0, std::round(spec.frame / spec.layout.cell));
  const double s_min = spec.layout.min_feature / cell, s_max = 1.0 - s_min;
  StencilCalibration c;
  // Just inside the limits, so that round-off neither drops the smallest square nor fills the
  // cell of the largest.
  c.min_share = s_min * s_min * (1.0 + 1e-9);
  c.max_share = s_max * s_max * (1.0 - 1e-9);
  c.share = {0.0};
  c.density = {0.0};
  for (int k = 0; k < samples; ++k) {
    // Squares evenly spaced in side, a little inside the limits so that none is dropped or
    // filled by round-off.
    const double s = s_min + (s_max - s_min) * (0.02 + 0.96 * k / (samples - 1));
    const double a = s * s;
    const Stencil stencil = layout_stencil(
        [a](const Vec2&) { return a; }, {Vec2::Zero(), Vec2(spec.frame, spec.frame)}, spec.layout);
    const RunResult run = run_scene(stencil_scene(spec, stencil));
    if (!run.solve.converged) continue;  // an unconverged sample says nothing
    const Membrane& m = run.prepared.membrane;
    const double rho = interpolate(curve.area, curve.rho, mesh_area(m.state.x, m.sheet.triangles));
    c.share.push_back(a);
    c.measured.push_back(rho);
    c.density.push_back(std::max(rho, c.density.back()));  // keep the table monotone
    if (progress) progress(a, rho);
  }
  c.share.push_back(1.0);
  c.density.push_back(1.0);
  return c;
}

}  // namespace

double StencilCalibration::density_of(double a) const {
  return interpolate(share, density, a);
}

double StencilCalibration::share_for(double rho) const {
  const double a = interpolate(density, share, rho);
  if (a < min_share) return a < 0.5 * min_share ? 0.0 : min_share;
  if (a > max_share) return a < 0.5 * (max_share + 1.0) ? max_share : 1.0;
  return a;
}

StencilCalibration calibrate_stencil(const DesignSpec& spec, int samples,
                                     const std::function<void(double, double)>& progress) {
  if (samples < 2) throw std::invalid_argument("the calibration needs two samples at least");
  const CalibrationCache* cache = spec.calibration_cache.get();
  if (cache && cache->load)
    if (std::optional<StencilCalibration> stored = cache->load(spec, samples)) {
      stored->cached = true;
      return *stored;
    }
  StencilCalibration c = measure_calibration(spec, samples, progress);
  if (cache && cache->store) cache->store(spec, samples, c);
  return c;
}

}  // namespace membra
