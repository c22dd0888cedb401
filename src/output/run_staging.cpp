#include "membra/output/run_staging.hpp"

#include "membra/measure/shape.hpp"

namespace membra {

namespace {

// Stresses in the outputs' unit: Pa to MPa. (Curvature is shown in 1/m^2, SI's own.)
std::vector<double> in_mpa(const std::vector<double>& si) {
  std::vector<double> out;
  out.reserve(si.size());
  for (double v : si) out.push_back(v * 1e-6);
  return out;
}

}  // namespace

RunColors run_colors(const RunResult& r, const PictureOptions& opts) {
  RunColors c;
  c.curvature = r.curvature.density;   // 1/m^2
  c.stress = in_mpa(r.vertex_stress);  // MPa
  std::tie(c.k_lo, c.k_hi) = symmetric_percentile_range(c.curvature, kCurvaturePercentile, 1.0);
  if (opts.curvature_range.size() == 2)
    c.k_lo = opts.curvature_range[0], c.k_hi = opts.curvature_range[1];
  std::tie(c.s_lo, c.s_hi) = symmetric_range(c.stress, 1e-3);
  if (opts.stress_range.size() == 2) c.s_lo = opts.stress_range[0], c.s_hi = opts.stress_range[1];
  return c;
}

std::vector<ColourScale> run_scales(const RunColors& c, ColourMap map) {
  return {{"Gaussian curvature", "1/m^2", c.k_lo, c.k_hi, map},
          {"Stress", "MPa", c.s_lo, c.s_hi, map}};
}

namespace {

Colouring colouring(const std::vector<double>& values, double lo, double hi, ColourMap map) {
  return {colorize(values, lo, hi, map), lo, hi};
}

// The global form (wrinkles finer than the window averaged out, measure/shape.hpp) coloured by
// its own Gaussian curvature, on the range of the particles a window (1/8 of the sheet) or more
// inside the edge: the averaging window is cut off at the edge, which bends the global form's
// rim more sharply than the form itself.
void stage_global(const RunResult& r, const PictureOptions& opts, RunStaging& s) {
  const auto& mesh = r.prepared.membrane.sheet;
  s.global_form = global_form(r.prepared.membrane.state.x, mesh.model.reference);
  if (s.global_form.cols() != r.prepared.membrane.state.x.cols()) {
    s.global_form.resize(3, 0);
    return;
  }
  const std::vector<double>& k = r.curvature_global.density;
  std::vector<double> interior;
  const GridSheet& g = mesh.grid;
  for (int p = 0; p < g.num_particles(); ++p) {
    const auto [i, j] = g.node(p);
    if (8 * i >= g.nx() && 8 * i <= 7 * g.nx() && 8 * j >= g.ny() && 8 * j <= 7 * g.ny())
      interior.push_back(k[static_cast<size_t>(p)]);
  }
  if (mesh.continuum())
    for (int p = 0; p < mesh.model.num_particles(); ++p) {
      const Vec2 u =
          mesh.model.reference.col(p).head<2>().cwiseQuotient(Vec2(g.width(), g.height()));
      if ((u.array() >= 0.125).all() && (u.array() <= 0.875).all())
        interior.push_back(k[static_cast<size_t>(p)]);
    }
  auto [lo, hi] =
      symmetric_percentile_range(interior.empty() ? k : interior, kCurvaturePercentile, 1.0);
  if (opts.curvature_range.size() == 2) lo = opts.curvature_range[0], hi = opts.curvature_range[1];
  s.global = colouring(k, lo, hi, s.options.colormap);
}

// Frames share one stress range.
void stage_frames(const RunResult& r, RunStaging& s) {
  std::vector<std::vector<double>> mpa;
  std::vector<double> all;
  for (const auto& f : r.frames) {
    mpa.push_back(in_mpa(f.stress));
    all.insert(all.end(), mpa.back().begin(), mpa.back().end());
  }
  const auto [lo, hi] = symmetric_range(all, 1e-3);
  for (const auto& m : mpa) s.frames.push_back(colouring(m, lo, hi, s.options.colormap));
}

// The curvature map's target and the measured curvature on the target's range.
void stage_curvature_map(const RunResult& r, const PictureOptions& opts, RunStaging& s) {
  const std::vector<double>& target = r.curvature_map->target;
  auto [lo, hi] = symmetric_range(target, 1.0);
  if (opts.curvature_range.size() == 2) lo = opts.curvature_range[0], hi = opts.curvature_range[1];
  s.target = colouring(target, lo, hi, s.options.colormap);
  s.measured = colouring(s.colors.curvature, lo, hi, s.options.colormap);
}

// Coats on the bottom face go on a layer of their own.
void stage_patterns(const Scene& scene, RunStaging& s) {
  s.top = scene_pattern(scene, false);
  s.bottom = scene_pattern(scene, true);
  if (!s.top && !s.bottom) return;
  s.frame = scene_frame(scene);
  const auto draw = [&](const PatternPtr& p) {
    return p ? stencil_outline(*p, s.frame) : std::vector<CurveLoop>{};
  };
  s.outlines = draw(s.top);
  s.underside = draw(s.bottom);
}

}  // namespace

RunStaging prepare_run_staging(const Scene& scene, const RunResult& r, const PictureOptions& opts) {
  RunStaging s;
  s.options = opts;
  s.options.colormap = scene.output.colormap;
  s.colors = run_colors(r, opts);
  const RunColors& c = s.colors;
  s.curvature_rgb = colorize(c.curvature, c.k_lo, c.k_hi, s.options.colormap);
  s.stress_rgb = colorize(c.stress, c.s_lo, c.s_hi, s.options.colormap);
  stage_global(r, opts, s);
  // Each stable form of an exploration, on the main picture's curvature range.
  for (const auto& b : r.branches)
    s.branches.push_back(colouring(b.run.curvature.density, c.k_lo, c.k_hi, s.options.colormap));
  stage_frames(r, s);
  if (r.curvature_map) stage_curvature_map(r, opts, s);
  stage_patterns(scene, s);
  return s;
}

}  // namespace membra
