#include "membra/io/pattern_reader.hpp"

#include <cmath>
#include <numbers>

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
const std::vector<std::string_view> kImageKeys = {"file", "origin", "size", "threshold", "invert"};

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

Vec2 read_vec2(const JsonObject& o, std::string_view key, Bounds b = {}) {
  const auto v = o.numbers(key, 2, b);
  return Vec2(v[0], v[1]) * units::mm;
}

double degrees(const JsonObject& o) {
  return o.number("angle", 0.0, Bounds::between(-360, 360)) * std::numbers::pi / 180.0;
}

}  // namespace

PatternPtr read_pattern(const json& j, const std::string& pointer,
                        const std::filesystem::path& base_dir, const Vec2& frame_size) {
  if (!j.is_object() || j.size() != 1) {
    std::string list;
    for (auto k : kKinds) list += (list.empty() ? "" : ", ") + std::string(k);
    throw InputError(pointer, "a pattern is an object with exactly one key: " + list);
  }
  const JsonObject outer(j, pointer, kKinds);
  const std::string kind = j.begin().key();
  const json& body = j.begin().value();
  const std::string ptr = outer.pointer(kind);

  if (kind == "union" || kind == "difference") {
    if (!body.is_array() || body.empty())
      throw InputError(ptr, "expected a non-empty array of patterns");
    std::vector<PatternPtr> parts;
    for (size_t i = 0; i < body.size(); ++i)
      parts.push_back(read_pattern(body[i], ptr + "/" + std::to_string(i), base_dir, frame_size));
    return kind == "union" ? make_union(std::move(parts)) : make_difference(std::move(parts));
  }
  if (kind == "strip") {
    const JsonObject o(body, ptr, kStripKeys);
    const double width = o.number("width", std::nullopt, Bounds::positive()) * units::mm;
    return make_strip(read_points(o, "points", 1), width);
  }
  if (kind == "ellipse") {
    const JsonObject o(body, ptr, kEllipseKeys);
    const Vec2 c = read_vec2(o, "center");
    const Vec2 r = read_vec2(o, "radii", Bounds::positive());
    if (o.has("ring_width"))
      return make_ellipse_ring(
          c, r.x(), r.y(), degrees(o),
          o.number("ring_width", std::nullopt, Bounds::positive()) * units::mm);
    return make_ellipse(c, r.x(), r.y(), degrees(o));
  }
  if (kind == "circle") {
    const JsonObject o(body, ptr, kCircleKeys);
    const double r = o.number("radius", std::nullopt, Bounds::positive()) * units::mm;
    return make_ellipse(read_vec2(o, "center"), r, r, 0.0);
  }
  if (kind == "hyperbola") {
    const JsonObject o(body, ptr, kHyperbolaKeys);
    const Vec2 c = read_vec2(o, "center");
    const double a = o.number("a", std::nullopt, Bounds::positive()) * units::mm;
    const double b = o.number("b", std::nullopt, Bounds::positive()) * units::mm;
    const double width = o.number("width", std::nullopt, Bounds::positive()) * units::mm;
    const std::string opens = o.string("opens", "x", {"x", "y", "both"});
    const double reach = frame_size.norm();
    if (opens == "both")
      return make_union({make_hyperbola(c, a, b, degrees(o), width, true, reach),
                         make_hyperbola(c, a, b, degrees(o), width, false, reach)});
    return make_hyperbola(c, a, b, degrees(o), width, opens == "x", reach);
  }
  if (kind == "polygon") {
    const JsonObject o(body, ptr, kPolygonKeys);
    return make_polygon(read_points(o, "points", 3));
  }
  // image
  const JsonObject o(body, ptr, kImageKeys);
  const std::string file = o.string("file", std::nullopt);
  const std::filesystem::path path = base_dir / file;
  const GreyImage img = load_grey_image(path, o.pointer("file"));
  const Vec2 origin = o.has("origin") ? read_vec2(o, "origin") : Vec2::Zero();
  const Vec2 size = o.has("size") ? read_vec2(o, "size", Bounds::positive()) : frame_size;
  return make_raster(img.value, img.width, img.height, origin, size,
                     o.number("threshold", 0.5, Bounds::between(0.0, 1.0)),
                     o.boolean("invert", false));
}

std::map<std::string, std::vector<std::string>> pattern_known_keys() {
  return {{"", to_strings(kKinds)},
          {"strip", to_strings(kStripKeys)},
          {"ellipse", to_strings(kEllipseKeys)},
          {"circle", to_strings(kCircleKeys)},
          {"hyperbola", to_strings(kHyperbolaKeys)},
          {"polygon", to_strings(kPolygonKeys)},
          {"image", to_strings(kImageKeys)}};
}

}  // namespace membra
