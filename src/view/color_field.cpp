#include "membra/view/color_field.hpp"

#include <algorithm>

#include "membra/core/units.hpp"
#include "membra/measure/curvature.hpp"
#include "membra/measure/fitted_curvature.hpp"
#include "membra/measure/stress.hpp"
#include "membra/model/triangle_resin.hpp"

namespace membra {

namespace {

// Each particle's share of resin: the mean over its springs' resin fractions on the lattice, over
// its triangles on the continuum (a triangle is resin or not; the continuum has no springs).
std::vector<double> resin_share(const Sheet& sheet) {
  const auto n = static_cast<size_t>(sheet.model.num_particles());
  std::vector<double> share(n, 0.0), count(n, 0.0);
  const auto add = [&](int p, double r) {
    share[static_cast<size_t>(p)] += r;
    count[static_cast<size_t>(p)] += 1.0;
  };
  if (sheet.continuum()) {
    const std::vector<bool> resin = triangle_resin(sheet);
    for (size_t t = 0; t < sheet.triangles.size(); ++t)
      for (int p : sheet.triangles[t]) add(p, resin[t] ? 1.0 : 0.0);
  } else {
    const Springs& s = sheet.model.springs;
    for (int i = 0; i < s.size(); ++i)
      for (int p : {s.a[i], s.b[i]}) add(p, s.resin_fraction[static_cast<size_t>(i)]);
  }
  for (size_t p = 0; p < n; ++p)
    if (count[p] > 0.0) share[p] /= count[p];
  return share;
}

}  // namespace

const char* color_mode_name(ColorMode mode) {
  switch (mode) {
    case ColorMode::stress:
      return "stress";
    case ColorMode::curvature:
      return "curvature";
    case ColorMode::pattern:
      return "pattern";
  }
  return "?";
}

std::optional<ColorMode> parse_color_mode(const std::string& name) {
  for (ColorMode m : {ColorMode::stress, ColorMode::curvature, ColorMode::pattern})
    if (name == color_mode_name(m)) return m;
  return std::nullopt;
}

ColorField color_field(const ViewerSession& session, ColorMode mode) {
  const Membrane& m = session.membrane();
  const Model& model = m.sheet.model;
  const Points& x = m.state.x;
  ColorField f;
  switch (mode) {
    case ColorMode::stress: {
      f.values = vertex_stress(model, x, m.sheet.material.thickness);
      for (double& v : f.values) v /= units::MPa;
      std::tie(f.lo, f.hi) = symmetric_range(f.values, 1e-6);
      f.title = "spring stress";
      f.unit = "MPa";
      break;
    }
    case ColorMode::curvature: {
      GaussianCurvature k = gaussian_curvature(x, m.sheet.triangles);
      if (m.sheet.continuum())
        smooth_density_on_mesh(x, m.sheet.triangles, k);
      else if (session.scene().benchmark_n == 0)
        smooth_density_on_grid(m.sheet.grid, k);
      f.values = k.density;  // 1/m^2, the unit every output shows
      std::tie(f.lo, f.hi) = symmetric_range(f.values, 1e-6);
      f.title = "Gaussian curvature";
      f.unit = "1/m^2";
      break;
    }
    case ColorMode::pattern: {
      f.values = resin_share(m.sheet);
      const PatternPtr pending = session.resin_pattern();
      if (pending)  // what the next impregnate would add shows too
        for (int p = 0; p < model.num_particles(); ++p)
          if (pending->contains(x.col(p).head<2>())) f.values[p] = 1.0;
      f.lo = 0.0;
      f.hi = 1.0;
      f.title = "resin";
      f.unit = "share";
      break;
    }
  }
  return f;
}

std::vector<Rgb> field_colors(const ColorField& field,
                              const std::optional<std::pair<double, double>>& range) {
  const auto [lo, hi] = range ? *range : std::pair{field.lo, field.hi};
  return colorize(field.values, lo, hi);
}

}  // namespace membra
