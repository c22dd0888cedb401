#include "membra/model/pattern_spec.hpp"

#include <numbers>

namespace membra {
namespace {

std::vector<PatternPtr> make_parts(const PatternSpec& s, const Vec2& frame_size) {
  std::vector<PatternPtr> parts;
  for (const PatternSpec& p : s.parts) parts.push_back(make_pattern(p, frame_size));
  return parts;
}

PatternPtr make_hyperbola_pattern(const PatternSpec& s, const Vec2& frame_size) {
  const double angle = s.angle_degrees * std::numbers::pi / 180.0;
  const double reach = frame_size.norm();
  if (s.opens == "both")
    return make_union({make_hyperbola(s.center, s.a, s.b, angle, s.width, true, reach),
                       make_hyperbola(s.center, s.a, s.b, angle, s.width, false, reach)});
  return make_hyperbola(s.center, s.a, s.b, angle, s.width, s.opens == "x", reach);
}

}  // namespace

PatternPtr make_pattern(const PatternSpec& s, const Vec2& frame_size) {
  const double angle = s.angle_degrees * std::numbers::pi / 180.0;
  switch (s.kind) {
    case PatternSpec::Kind::strip:
      return make_strip(s.points, s.width);
    case PatternSpec::Kind::ellipse:
      if (s.ring_width)
        return make_ellipse_ring(s.center, s.radii.x(), s.radii.y(), angle, *s.ring_width);
      return make_ellipse(s.center, s.radii.x(), s.radii.y(), angle);
    case PatternSpec::Kind::circle:
      return make_ellipse(s.center, s.radius, s.radius, 0.0);
    case PatternSpec::Kind::hyperbola:
      return make_hyperbola_pattern(s, frame_size);
    case PatternSpec::Kind::polygon:
      return make_polygon(s.points);
    case PatternSpec::Kind::image:
      return make_raster(s.image.value, s.image.width, s.image.height,
                         s.origin.value_or(Vec2::Zero()), s.size.value_or(frame_size), s.threshold,
                         s.invert);
    case PatternSpec::Kind::union_of:
      return make_union(make_parts(s, frame_size));
    case PatternSpec::Kind::difference:
      return make_difference(make_parts(s, frame_size));
  }
  return nullptr;
}

PatternSpec circle_spec(const Vec2& center, double radius) {
  PatternSpec s;
  s.kind = PatternSpec::Kind::circle;
  s.center = center;
  s.radius = radius;
  return s;
}

PatternSpec polygon_spec(std::vector<Vec2> points) {
  PatternSpec s;
  s.kind = PatternSpec::Kind::polygon;
  s.points = std::move(points);
  return s;
}

PatternSpec union_spec(std::vector<PatternSpec> parts) {
  PatternSpec s;
  s.kind = PatternSpec::Kind::union_of;
  s.parts = std::move(parts);
  return s;
}

PatternSpec difference_spec(std::vector<PatternSpec> parts) {
  PatternSpec s;
  s.kind = PatternSpec::Kind::difference;
  s.parts = std::move(parts);
  return s;
}

}  // namespace membra
