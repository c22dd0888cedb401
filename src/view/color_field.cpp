#include "membra/view/color_field.hpp"

#include <algorithm>

#include "membra/core/units.hpp"
#include "membra/measure/curvature.hpp"
#include "membra/measure/fitted_curvature.hpp"
#include "membra/measure/stress.hpp"

namespace membra {

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
      f.values.assign(static_cast<size_t>(model.num_particles()), 0.0);
      const PatternPtr pending = session.resin_pattern();
      const std::vector<double>& resin = model.springs.resin_fraction;
      const bool impregnated =
          std::any_of(resin.begin(), resin.end(), [](double r) { return r > 0.0; });
      if (impregnated) {
        std::vector<double> count(f.values.size(), 0.0);
        const Springs& s = model.springs;
        for (int i = 0; i < s.size(); ++i)
          for (int p : {s.a[i], s.b[i]}) {
            f.values[p] += resin[i];
            count[p] += 1.0;
          }
        for (size_t p = 0; p < f.values.size(); ++p)
          if (count[p] > 0.0) f.values[p] /= count[p];
      }
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
