#pragma once
// Numbers as a reader wants them on a legend or a report page: curvature in 1/m² rather than
// 6.3e-06 1/mm², a small stress in kPa rather than 0.00042 MPa, and the digits the spacing of
// the values calls for. Pure functions (headers only), shared by the pictures and report.html.
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

// The readable unit for values of magnitude up to `max_abs` given in `unit`. Knows curvature
// ("1/mm^2": 1/m² up to 1e4 1/m², a radius of 1 cm; 1/mm² beyond), stress ("MPa": MPa from 0.1
// MPa, kPa from 0.1 kPa, Pa below) and lengths ("mm"); other units are kept, with ^2 shown as ².
inline DisplayUnit readable_unit(const std::string& unit, double max_abs) {
  if (unit == "1/mm^2")
    return max_abs * 1e6 < 1e4 ? DisplayUnit{1e6, "1/m²"} : DisplayUnit{1.0, "1/mm²"};
  if (unit == "MPa") {
    if (max_abs >= 0.1) return {1.0, "MPa"};
    return max_abs * 1e3 >= 0.1 ? DisplayUnit{1e3, "kPa"} : DisplayUnit{1e6, "Pa"};
  }
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

}  // namespace membra
