#include "membra/io/pattern_reader.hpp"

#include <cmath>

#include "membra/core/units.hpp"
#include "membra/io/image.hpp"
#include "membra/io/json_reader.hpp"

namespace membra {
namespace {

using nlohmann::json;

const std::vector<std::string_view> kKinds = {"strip",   "ellipse", "circle", "hyperbola",
                                              "polygon", "image",   "union",  "difference"};
const std::vector<std::string_view> kCircleKeys = {"center", "radius"};
const std::vector<std::string_view> kStripKeys = {"points", "width"};
const std::vector<std::string_view> kEllipseKeys = {"center", "radii", "angle", "ring_width"};
const std::vector<std::string_view> kHyperbolaKeys = {"center", "a",     "b",
                                                      "angle",  "width", "opens"};
const std::vector<std::string_view> kPolygonKeys = {"points"};
const std::vector<std::string_view> kPatternImageKeys = {"file", "origin", "size", "threshold",
                                                         "invert"};

}  // namespace

std::vector<Vec2> read_points(const JsonObject& o, std::string_view key, size_t min_count) {
  const auto& arr = o.at(key);
  if (!arr.is_array() || arr.size() < min_count)
    throw InputError(o.pointer(key), "expected an array of at least " + std::to_string(min_count) +
                                         " [x, y] points (mm)");
  std::vector<Vec2> pts;
  for (size_t i = 0; i < arr.size(); ++i) {
    const std::string ptr = o.pointer(key) + "/" + std::to_string(i);
    if (!arr[i].is_array() || arr[i].size() != 2) throw InputError(ptr, "expected [x, y] in mm");
    pts.emplace_back(checked_number(arr[i][0], ptr + "/0", {}) * units::mm,
                     checked_number(arr[i][1], ptr + "/1", {}) * units::mm);
  }
  return pts;
}

namespace {

Vec2 read_vec2(const JsonObject& o, std::string_view key, Bounds b = {}) {
  const auto v = o.numbers(key, 2, b);
  return Vec2(v[0], v[1]) * units::mm;
}

double degrees(const JsonObject& o) {
  return o.number("angle", 0.0, Bounds::between(-360, 360));
}

void read_image(const JsonObject& o, const std::filesystem::path& base_dir, PatternSpec& s) {
  s.kind = PatternSpec::Kind::image;
  s.file = o.string("file", std::nullopt);
  s.image = load_grey_image(base_dir / s.file, o.pointer("file"));
  if (o.has("origin")) s.origin = read_vec2(o, "origin");
  if (o.has("size")) s.size = read_vec2(o, "size", Bounds::positive());
  s.threshold = o.number("threshold", 0.5, Bounds::between(0.0, 1.0));
  s.invert = o.boolean("invert", false);
}

}  // namespace

PatternSpec read_pattern_spec(const json& j, const std::string& pointer,
                              const std::filesystem::path& base_dir) {
  if (!j.is_object() || j.size() != 1) {
    std::string list;
    for (auto k : kKinds) list += (list.empty() ? "" : ", ") + std::string(k);
    throw InputError(pointer, "a pattern is an object with exactly one key: " + list);
  }
  const JsonObject outer(j, pointer, kKinds);
  const std::string kind = j.begin().key();
  const json& body = j.begin().value();
  const std::string ptr = outer.pointer(kind);
  PatternSpec s;
  if (kind == "union" || kind == "difference") {
    if (!body.is_array() || body.empty())
      throw InputError(ptr, "expected a non-empty array of patterns");
    s.kind = kind == "union" ? PatternSpec::Kind::union_of : PatternSpec::Kind::difference;
    for (size_t i = 0; i < body.size(); ++i)
      s.parts.push_back(read_pattern_spec(body[i], ptr + "/" + std::to_string(i), base_dir));
  } else if (kind == "strip") {
    const JsonObject o(body, ptr, kStripKeys);
    s.kind = PatternSpec::Kind::strip;
    s.width = o.number("width", std::nullopt, Bounds::positive()) * units::mm;
    s.points = read_points(o, "points", 1);
  } else if (kind == "ellipse") {
    const JsonObject o(body, ptr, kEllipseKeys);
    s.kind = PatternSpec::Kind::ellipse;
    s.center = read_vec2(o, "center");
    s.radii = read_vec2(o, "radii", Bounds::positive());
    s.angle_degrees = degrees(o);
    if (o.has("ring_width"))
      s.ring_width = o.number("ring_width", std::nullopt, Bounds::positive()) * units::mm;
  } else if (kind == "circle") {
    const JsonObject o(body, ptr, kCircleKeys);
    s.kind = PatternSpec::Kind::circle;
    s.radius = o.number("radius", std::nullopt, Bounds::positive()) * units::mm;
    s.center = read_vec2(o, "center");
  } else if (kind == "hyperbola") {
    const JsonObject o(body, ptr, kHyperbolaKeys);
    s.kind = PatternSpec::Kind::hyperbola;
    s.center = read_vec2(o, "center");
    s.a = o.number("a", std::nullopt, Bounds::positive()) * units::mm;
    s.b = o.number("b", std::nullopt, Bounds::positive()) * units::mm;
    s.width = o.number("width", std::nullopt, Bounds::positive()) * units::mm;
    s.opens = o.string("opens", "x", {"x", "y", "both"});
    s.angle_degrees = degrees(o);
  } else if (kind == "polygon") {
    const JsonObject o(body, ptr, kPolygonKeys);
    s.kind = PatternSpec::Kind::polygon;
    s.points = read_points(o, "points", 3);
  } else {
    read_image(JsonObject(body, ptr, kPatternImageKeys), base_dir, s);
  }
  return s;
}

std::map<std::string, std::vector<std::string>> pattern_known_keys() {
  return {{"", to_strings(kKinds)},
          {"strip", to_strings(kStripKeys)},
          {"ellipse", to_strings(kEllipseKeys)},
          {"circle", to_strings(kCircleKeys)},
          {"hyperbola", to_strings(kHyperbolaKeys)},
          {"polygon", to_strings(kPolygonKeys)},
          {"image", to_strings(kPatternImageKeys)}};
}

}  // namespace membra
