#pragma once
// Numbers as a reader wants them on a legend or a report page: one unit per quantity everywhere
// (docs/outputs.md, "Units": Gaussian curvature in 1/m², stress in MPa), with the digits the
// spacing of the values calls for. Pure functions (headers only), shared by the pictures, the
// viewer and report.html.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace membra {

// A unit to show values in: shown = value * factor.
struct DisplayUnit {
  double factor = 1.0;
  std::string unit;
};

// The unit to show values given in `unit` in: Gaussian curvature always in 1/m² (given in
// "1/m^2" or "1/mm^2"), stress in MPa, lengths as given; ^2 is shown as ². (`max_abs` is kept for
// callers; one unit per quantity means it no longer picks one.)
inline DisplayUnit readable_unit(const std::string& unit, double max_abs) {
  (void)max_abs;
  if (unit == "1/mm^2") return {1e6, "1/m²"};
  std::string shown;
  for (size_t i = 0; i < unit.size(); ++i) {
    const bool squared = unit[i] == '^' && i + 1 < unit.size() && unit[i + 1] == '2';
    shown += squared ? "²" : unit.substr(i, 1);
    i += squared ? 1 : 0;
  }
  return {1.0, shown};
}

// `v` with the decimals that a spacing of `step` between neighbouring values needs (two
// significant digits of the step), a true minus sign, and exponent form only for values that
// would need more than six digits either way.
inline std::string format_number(double v, double step) {
  char buf[64];
  const double mag = std::max(std::abs(v), std::abs(step));
  if (!std::isfinite(v)) return "n/a";
  if (mag != 0.0 && (mag >= 1e6 || mag < 1e-4)) {
    std::snprintf(buf, sizeof buf, "%.2e", v);
  } else {
    const double s = step > 0.0 ? step : (mag > 0.0 ? mag : 1.0);
    const int decimals = std::clamp(1 - static_cast<int>(std::floor(std::log10(s))), 0, 6);
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  }
  std::string out = buf;
  if (out == "-0" || out.find_first_not_of("-0.") == std::string::npos) out.erase(0, out[0] == '-');
  if (!out.empty() && out[0] == '-') out.replace(0, 1, "\u2212");
  return out;
}

// `count` evenly spaced labels from lo to hi (values in `unit`), in the readable unit.
struct Ticks {
  std::string unit;
  std::vector<std::string> labels;
};
inline Ticks readable_ticks(double lo, double hi, const std::string& unit, int count) {
  const DisplayUnit d = readable_unit(unit, std::max(std::abs(lo), std::abs(hi)));
  Ticks t{d.unit, {}};
  const double step = (hi - lo) * d.factor / std::max(1, count - 1);
  for (int i = 0; i < count; ++i) {
    const double v = (lo + (hi - lo) * i / std::max(1, count - 1)) * d.factor;
    t.labels.push_back(format_number(v, step));
  }
  return t;
}

// A box's size given in metres, as the pictures and the viewer head it: "218 × 163 × 81 mm".
inline std::string box_dimensions(double x, double y, double z) {
  char text[96];
  std::snprintf(text, sizeof text, "%.0f \u00d7 %.0f \u00d7 %.0f mm", x * 1e3, y * 1e3, z * 1e3);
  return text;
}

}  // namespace membra
