#include "membra/measure/colormap.hpp"

#include <algorithm>
#include <cmath>

namespace membra {

Rgb colormap(double v, double lo, double hi) {
  const double t = hi > lo ? std::clamp((v - lo) / (hi - lo), 0.0, 1.0) : 0.5;
  if (t <= 0.5) {
    const float s = static_cast<float>(2.0 * t);
    return {0.0f, s, 1.0f - s};
  }
  const float s = static_cast<float>(2.0 * t - 1.0);
  return {s, 1.0f - s, 0.0f};
}

std::vector<Rgb> colorize(const std::vector<double>& values, double lo, double hi) {
  std::vector<Rgb> out;
  out.reserve(values.size());
  for (double v : values) out.push_back(colormap(v, lo, hi));
  return out;
}

std::pair<double, double> symmetric_range(const std::vector<double>& values, double floor) {
  double m = floor;
  for (double v : values) m = std::max(m, std::abs(v));
  return {-m, m};
}

std::pair<double, double> symmetric_percentile_range(const std::vector<double>& values, double q,
                                                     double floor) {
  std::vector<double> mags;
  for (double v : values)
    if (v != 0.0 && std::isfinite(v)) mags.push_back(std::abs(v));
  if (mags.empty()) return {-floor, floor};
  const auto k = static_cast<std::ptrdiff_t>(std::ceil(q * static_cast<double>(mags.size()))) - 1;
  const auto at = mags.begin() + std::clamp<std::ptrdiff_t>(k, 0, std::ssize(mags) - 1);
  std::nth_element(mags.begin(), at, mags.end());
  const double m = std::max(floor, *at);
  return {-m, m};
}

}  // namespace membra
