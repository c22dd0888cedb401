#pragma once
// A pattern's description: what a scene says of it (a primitive with its numbers, a grey image
// placed on the frame, a union or a difference), in SI. make_pattern() builds the shape that
// answers "is this point resin?"; the description is kept beside it so that a scene can be
// written back (io/scene_writer.hpp).
#include <optional>
#include <string>
#include <vector>

#include "membra/core/grey_image.hpp"
#include "membra/model/pattern.hpp"

namespace membra {

struct PatternSpec {
  enum class Kind { strip, ellipse, circle, hyperbola, polygon, image, union_of, difference };
  Kind kind = Kind::polygon;
  std::vector<Vec2> points;          // strip (>= 1), polygon (>= 3): frame coordinates, m
  double width = 0.0;                // strip, hyperbola: band width, m
  Vec2 center = Vec2::Zero();        // ellipse, circle, hyperbola, m
  Vec2 radii = Vec2::Zero();         // ellipse: semi-axes, m
  double radius = 0.0;               // circle, m
  double angle_degrees = 0.0;        // ellipse, hyperbola: rotation about the centre
  std::optional<double> ring_width;  // ellipse: a ring of this width on the outline, m
  double a = 0.0, b = 0.0;           // hyperbola: x^2/a^2 - y^2/b^2 = 1, m
  std::string opens = "x";           // hyperbola: x | y | both
  // image: resin where the grey value is below the threshold (at/above when inverted)
  std::string file;  // as the scene names it (relative to the scene)
  GreyImage image;
  std::optional<Vec2> origin, size;  // placement, m (default: the whole frame)
  double threshold = 0.5;
  bool invert = false;
  std::vector<PatternSpec> parts;  // union_of, difference (the first minus the others)
};

// The shape a description stands for. `frame_size` (m): the stretched frame, across which
// hyperbola branches extend and an image without a size is stretched.
PatternPtr make_pattern(const PatternSpec& spec, const Vec2& frame_size);

// A circle (the viewer's brush and hole), a polygon, a union and a difference, as descriptions.
PatternSpec circle_spec(const Vec2& center, double radius);
PatternSpec polygon_spec(std::vector<Vec2> points);
PatternSpec union_spec(std::vector<PatternSpec> parts);
PatternSpec difference_spec(std::vector<PatternSpec> parts);

}  // namespace membra
