#include "membra/model/field_spec.hpp"

#include <algorithm>
#include <memory>

namespace membra {
namespace {

ScalarField formula_field(const std::string& text, const FormulaContext& context) {
  auto f = std::make_shared<Formula>(text, context);
  return [f](const Vec2& p) { return (*f)(p); };
}

// Bilinear samples of the image stretched over [origin, origin + size]; row 0 is the top.
ScalarField image_field(const FieldSpec& s, const Vec2& sheet_size) {
  auto grey = std::make_shared<std::vector<float>>(s.image.value);
  const int w = s.image.width, h = s.image.height;
  const Vec2 origin = s.origin.value_or(Vec2::Zero()), size = s.size.value_or(sheet_size);
  const double lo = s.range.x(), hi = s.range.y();
  return [grey, w, h, origin, size, lo, hi](const Vec2& p) {
    const double u = std::clamp((p.x() - origin.x()) / size.x(), 0.0, 1.0) * (w - 1);
    const double v = std::clamp(1.0 - (p.y() - origin.y()) / size.y(), 0.0, 1.0) * (h - 1);
    const int i = std::min(static_cast<int>(u), std::max(w - 2, 0));
    const int j = std::min(static_cast<int>(v), std::max(h - 2, 0));
    const int i1 = std::min(i + 1, w - 1), j1 = std::min(j + 1, h - 1);
    const double fu = u - i, fv = v - j;
    auto at = [&](int x, int y) { return static_cast<double>((*grey)[y * w + x]); };
    const double g = (1 - fv) * ((1 - fu) * at(i, j) + fu * at(i1, j)) +
                     fv * ((1 - fu) * at(i, j1) + fu * at(i1, j1));
    return lo + g * (hi - lo);
  };
}

}  // namespace

std::string field_preset(const std::string& name) {
  if (name == "sin2_x") return "1 + a*sin(pi*x/w)^2";
  if (name == "sin2_y") return "1 + a*sin(pi*y/h)^2";
  if (name == "radial") return "1 + a*(2*r/min(w, h))^2";
  return "";
}

ScalarField make_field(const FieldSpec& s, const FormulaContext& context) {
  switch (s.kind) {
    case FieldSpec::Kind::constant:
      return [v = s.value](const Vec2&) { return v; };
    case FieldSpec::Kind::formula:
      return formula_field(s.formula, context);
    case FieldSpec::Kind::preset: {
      FormulaContext c = context;
      c.a = s.amplitude;
      return formula_field(field_preset(s.preset), c);
    }
    case FieldSpec::Kind::image:
      return image_field(s, context.size);
  }
  return {};
}

}  // namespace membra
