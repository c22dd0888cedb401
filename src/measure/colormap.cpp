#include "membra/measure/colormap.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace membra {

namespace {

// ColorBrewer RdBu, 11 classes, from its negative (blue) end to its positive (red) end.
constexpr float kRdBu[11][3] = {{5, 48, 97},     {33, 102, 172},  {67, 147, 195},  {146, 197, 222},
                                {209, 229, 240}, {247, 247, 247}, {253, 219, 199}, {244, 165, 130},
                                {214, 96, 77},   {178, 24, 43},   {103, 0, 31}};

Rgb diverging(double t) {
  const double x = t * 10.0;
  const int i = std::min(9, static_cast<int>(x));
  const float f = static_cast<float>(x - i);
  Rgb c;
  for (int k = 0; k < 3; ++k) c[k] = ((1.0f - f) * kRdBu[i][k] + f * kRdBu[i + 1][k]) / 255.0f;
  return c;
}

}  // namespace

const char* to_string(ColourMap map) {
  if (map == ColourMap::sequential) return "sequential";
  return map == ColourMap::paper ? "paper" : "diverging";
}

ColourMap colour_map_named(const std::string& name) {
  if (name == "diverging") return ColourMap::diverging;
  if (name == "paper") return ColourMap::paper;
  throw std::invalid_argument("unknown colour map '" + name + "': known are diverging, paper");
}

Rgb colormap(double v, double lo, double hi, ColourMap map) {
  double t = hi > lo ? std::clamp((v - lo) / (hi - lo), 0.0, 1.0) : 0.5;
  if (!(t == t)) t = 0.5;  // NaN: the middle, never an index out of the table
  if (map == ColourMap::diverging) return diverging(t);
  if (map == ColourMap::sequential) return diverging(0.5 + 0.5 * t);
  if (t <= 0.5) {
    const float s = static_cast<float>(2.0 * t);
    return {0.0f, s, 1.0f - s};
  }
  const float s = static_cast<float>(2.0 * t - 1.0);
  return {s, 1.0f - s, 0.0f};
}

std::vector<Rgb> colorize(const std::vector<double>& values, double lo, double hi, ColourMap map) {
  std::vector<Rgb> out;
  out.reserve(values.size());
  for (double v : values) out.push_back(colormap(v, lo, hi, map));
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
