#pragma once
// The per-particle values the viewer colours the sheet by, in display units, with the legend
// that explains them.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "membra/measure/colormap.hpp"
#include "membra/view/viewer_session.hpp"

namespace membra {

enum class ColorMode { stress, curvature, pattern };
const char* color_mode_name(ColorMode mode);
// "stress", "curvature" or "pattern"; nullopt otherwise.
std::optional<ColorMode> parse_color_mode(const std::string& name);

struct ColorField {
  std::vector<double> values;  // per particle, display units
  std::string title, unit;     // for the legend
  double lo = 0.0, hi = 1.0;   // automatic range: symmetric about 0 for stress and curvature
};

// stress: mean spring stress at each particle, MPa (tension > 0, red; compression blue).
// curvature: Gaussian curvature density (angle defect / area, smoothed), 1/m^2.
// pattern: share of resin (0 latex .. 1 resin): of the particle's springs once impregnated,
// of the pending brush/scene pattern at the particle before.
ColorField color_field(const ViewerSession& session, ColorMode mode);

// Colours for a field over [lo, hi] (a manual range when given, else the field's own).
std::vector<Rgb> field_colors(const ColorField& field,
                              const std::optional<std::pair<double, double>>& range);

}  // namespace membra
