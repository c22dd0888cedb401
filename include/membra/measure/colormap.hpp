#pragma once
// The colour maps of pictures, legends and pages (docs/outputs.md, "Colour"): by default a
// diverging map readable with every common colour-vision deficiency, and the paper's
// blue-green-red as a named option. Linear in between their stops, clamped outside [lo, hi].
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace membra {

using Rgb = Eigen::Vector3f;  // components in [0, 1]

// "diverging": ColorBrewer's RdBu (11 classes), dark blue at lo, white at the midpoint, dark
// red at hi; "paper": the paper's figures, (0,0,1) at lo, (0,1,0) at the midpoint, (1,0,0) at hi.
// "sequential" (pictures of unsigned quantities, a resin density or an error distance): RdBu's
// upper half, white at lo to dark red at hi.
enum class ColourMap { diverging, paper, sequential };
const char* to_string(ColourMap map);
// The map of that name; throws std::invalid_argument naming the known ones.
ColourMap colour_map_named(const std::string& name);

// Colour of value v on the range [lo, hi] (lo < hi); values outside take the end colours.
Rgb colormap(double v, double lo, double hi, ColourMap map = ColourMap::diverging);

// Colours of many values on [lo, hi].
std::vector<Rgb> colorize(const std::vector<double>& values, double lo, double hi,
                          ColourMap map = ColourMap::diverging);

// A range symmetric about 0 covering every value, at least [-floor, floor], so that the midpoint
// colour means zero (flat, unstressed) and round-off on a flat sheet stays there.
std::pair<double, double> symmetric_range(const std::vector<double>& values, double floor);

// A range symmetric about 0 covering the share `q` (e.g. 0.95) of the nonzero values by
// magnitude, at least [-floor, floor]: a few sharp wrinkles then saturate instead of washing the
// broad form out to the midpoint colour. Zeros (the rim, where the curvature is not defined) are
// left out.
std::pair<double, double> symmetric_percentile_range(const std::vector<double>& values, double q,
                                                     double floor);

}  // namespace membra
