#pragma once
// The colour map of the paper's figures: blue at lo, green at the midpoint, red at hi, linear in
// between and clamped outside [lo, hi].
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace membra {

using Rgb = Eigen::Vector3f;  // components in [0, 1]

// Colour of value v on the range [lo, hi] (lo < hi): (0,0,1) at lo, (0,1,0) at the midpoint,
// (1,0,0) at hi; values outside are clamped to the end colours.
Rgb colormap(double v, double lo, double hi);

// Colours of many values on [lo, hi].
std::vector<Rgb> colorize(const std::vector<double>& values, double lo, double hi);

// A range symmetric about 0 covering every value, at least [-floor, floor], so that green means
// zero (flat, unstressed) and round-off on a flat sheet stays green.
std::pair<double, double> symmetric_range(const std::vector<double>& values, double floor);

// A range symmetric about 0 covering the share `q` (e.g. 0.95) of the nonzero values by
// magnitude, at least [-floor, floor]: a few sharp wrinkles then saturate instead of washing the
// broad form out to green. Zeros (the rim, where the curvature is not defined) are left out.
std::pair<double, double> symmetric_percentile_range(const std::vector<double>& values, double q,
                                                     double floor);

}  // namespace membra
