#include "membra/io/field_reader.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "membra/core/units.hpp"
#include "membra/io/image.hpp"
#include "membra/io/json_reader.hpp"

namespace membra {
namespace {

const std::vector<std::string_view> kImageKeys = {"image", "range", "origin", "size"};
const std::vector<std::string_view> kPresetKeys = {"preset", "amplitude"};

ScalarField formula_field(const std::string& text, const std::string& pointer,
                          const FormulaContext& context) {
  try {
    auto f = std::make_shared<Formula>(text, context);
    return [f](const Vec2& p) { return (*f)(p); };
  } catch (const std::invalid_argument& e) {
    throw InputError(pointer, e.what());
  }
}

// Bilinear samples of the image stretched over [origin, origin + size]; row 0 is the top.
ScalarField image_field(GreyImage img, Vec2 origin, Vec2 size, double lo, double hi) {
  auto data = std::make_shared<GreyImage>(std::move(img));
  return [data, origin, size, lo, hi](const Vec2& p) {
    const GreyImage& g = *data;
    const double u = std::clamp((p.x() - origin.x()) / size.x(), 0.0, 1.0) * (g.width - 1);
    const double v = std::clamp(1.0 - (p.y() - origin.y()) / size.y(), 0.0, 1.0) * (g.height - 1);
    const int i = std::min(static_cast<int>(u), std::max(g.width - 2, 0));
    const int j = std::min(static_cast<int>(v), std::max(g.height - 2, 0));
    const int i1 = std::min(i + 1, g.width - 1), j1 = std::min(j + 1, g.height - 1);
    const double fu = u - i, fv = v - j;
    auto at = [&](int x, int y) { return static_cast<double>(g.value[y * g.width + x]); };
    const double grey = (1 - fv) * ((1 - fu) * at(i, j) + fu * at(i1, j)) +
                        fv * ((1 - fu) * at(i, j1) + fu * at(i1, j1));
    return lo + grey * (hi - lo);
  };
}

}  // namespace

std::string field_preset(const std::string& name) {
  if (name == "sin2_x") return "1 + a*sin(pi*x/w)^2";
  if (name == "sin2_y") return "1 + a*sin(pi*y/h)^2";
  if (name == "radial") return "1 + a*(2*r/min(w, h))^2";
  return "";
}

ScalarField read_field(const nlohmann::json& j, const std::string& pointer,
                       const std::filesystem::path& base_dir, const FormulaContext& context) {
  if (j.is_number()) {
    const double v = checked_number(j, pointer, {});
    return [v](const Vec2&) { return v; };
  }
  if (j.is_string()) return formula_field(j.get<std::string>(), pointer, context);
  if (j.is_object() && j.contains("preset")) {
    const JsonObject o(j, pointer, kPresetKeys);
    const std::string name = o.string("preset", std::nullopt, {"sin2_x", "sin2_y", "radial"});
    FormulaContext c = context;
    c.a = o.number("amplitude", 0.3, Bounds::between(-0.99, 10.0));
    return formula_field(field_preset(name), o.pointer("preset"), c);
  }
  if (j.is_object() && j.contains("image")) {
    const JsonObject o(j, pointer, kImageKeys);
    const GreyImage img =
        load_grey_image(base_dir / o.string("image", std::nullopt), o.pointer("image"));
    const auto range = o.numbers("range", 2);
    Vec2 origin = Vec2::Zero(), size = context.size;
    if (o.has("origin")) {
      const auto v = o.numbers("origin", 2);
      origin = Vec2(v[0], v[1]) * units::mm;
    }
    if (o.has("size")) {
      const auto v = o.numbers("size", 2, Bounds::positive());
      size = Vec2(v[0], v[1]) * units::mm;
    }
    return image_field(img, origin, size, range[0], range[1]);
  }
  throw InputError(pointer,
                   "expected a number, a formula string such as \"1 + 0.3*sin(pi*x/200)^2\", "
                   "{\"preset\": \"sin2_x\" | \"sin2_y\" | \"radial\", \"amplitude\": a} or "
                   "{\"image\": \"file.png\", \"range\": [lo, hi]}, got " +
                       json_type_name(j));
}

}  // namespace membra
