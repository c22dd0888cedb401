#include "membra/io/field_reader.hpp"

#include <stdexcept>

#include "membra/core/units.hpp"
#include "membra/io/image.hpp"
#include "membra/io/json_reader.hpp"

namespace membra {
namespace {

const std::vector<std::string_view> kFieldImageKeys = {"image", "range", "origin", "size"};
const std::vector<std::string_view> kPresetKeys = {"preset", "amplitude"};

void read_image_field(const JsonObject& o, const std::filesystem::path& base_dir, FieldSpec& s) {
  s.kind = FieldSpec::Kind::image;
  s.file = o.string("image", std::nullopt);
  s.image = load_grey_image(base_dir / s.file, o.pointer("image"));
  const auto range = o.numbers("range", 2);
  s.range = Vec2(range[0], range[1]);
  if (o.has("origin")) {
    const auto v = o.numbers("origin", 2);
    s.origin = Vec2(v[0], v[1]) * units::mm;
  }
  if (o.has("size")) {
    const auto v = o.numbers("size", 2, Bounds::positive());
    s.size = Vec2(v[0], v[1]) * units::mm;
  }
}

}  // namespace

FieldSpec read_field_spec(const nlohmann::json& j, const std::string& pointer,
                          const std::filesystem::path& base_dir) {
  FieldSpec s;
  if (j.is_number()) {
    s.kind = FieldSpec::Kind::constant;
    s.value = checked_number(j, pointer, {});
  } else if (j.is_string()) {
    s.kind = FieldSpec::Kind::formula;
    s.formula = j.get<std::string>();
  } else if (j.is_object() && j.contains("preset")) {
    const JsonObject o(j, pointer, kPresetKeys);
    s.kind = FieldSpec::Kind::preset;
    s.preset = o.string("preset", std::nullopt, {"sin2_x", "sin2_y", "radial"});
    s.amplitude = o.number("amplitude", 0.3, Bounds::between(-0.99, 10.0));
  } else if (j.is_object() && j.contains("image")) {
    read_image_field(JsonObject(j, pointer, kFieldImageKeys), base_dir, s);
  } else {
    throw InputError(pointer,
                     "expected a number, a formula string such as \"1 + 0.3*sin(pi*x/200)^2\", "
                     "{\"preset\": \"sin2_x\" | \"sin2_y\" | \"radial\", \"amplitude\": a} or "
                     "{\"image\": \"file.png\", \"range\": [lo, hi]}, got " +
                         json_type_name(j));
  }
  return s;
}

ScalarField build_field(const FieldSpec& spec, const std::string& pointer,
                        const FormulaContext& context) {
  try {
    return make_field(spec, context);
  } catch (const std::invalid_argument& e) {
    // A preset's formula is ours: a problem with it is reported at the preset's key.
    throw InputError(spec.kind == FieldSpec::Kind::preset ? pointer + "/preset" : pointer,
                     e.what());
  }
}

}  // namespace membra
