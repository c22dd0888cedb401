#pragma once
// Resin patterns: regions of the stretched frame, in frame coordinates (m, origin at the frame's
// lower-left corner). Primitives compose by union and difference. A pattern answers "is this
// point resin?" and "where could resin be?" (its bounding box).
#include <memory>
#include <vector>

#include "membra/core/vec.hpp"
#include "membra/geometry/plane_curve.hpp"

namespace membra {

// Axis-aligned box (min, max), m.
struct Box2 {
  Vec2 min = Vec2::Constant(std::numeric_limits<double>::infinity());
  Vec2 max = Vec2::Constant(-std::numeric_limits<double>::infinity());
  bool empty() const { return !(min.x() <= max.x() && min.y() <= max.y()); }
  void extend(const Vec2& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  void extend(const Box2& b) {
    if (!b.empty()) extend(b.min), extend(b.max);
  }
  Box2 intersect(const Box2& b) const { return {min.cwiseMax(b.min), max.cwiseMin(b.max)}; }
};

class Pattern;
using PatternPtr = std::shared_ptr<const Pattern>;

class Pattern {
 public:
  virtual ~Pattern() = default;
  // True where the point (frame coordinates, m) is resin.
  virtual bool contains(const Vec2& p) const = 0;
  // A box holding every resin point (may be larger than needed).
  virtual Box2 bounds() const = 0;
  // A field that is negative inside, positive outside and crosses zero smoothly on the outline
  // (a signed distance where one is cheap), so outlines can be traced between samples.
  virtual double field(const Vec2& p) const = 0;
  // True when field() outside bounds() is at least the distance to bounds() (a true signed
  // distance): a union then skips the parts too far away to be its nearest.
  virtual bool field_is_distance() const { return false; }

  // How the pattern is built, for the stencil's exact outline (model/pattern_stencil.hpp): a
  // primitive gives its outline as segments and elliptical arcs, or nothing when it has no
  // exact form (strips, rings, hyperbola bands, images: the stencil traces those); a union or a
  // difference gives its parts.
  enum class Combination { primitive, union_of, difference_of };
  virtual Combination combination() const { return Combination::primitive; }
  virtual std::vector<PatternPtr> parts() const { return {}; }
  virtual std::vector<PlaneCurve> exact_outline() const { return {}; }
};

// Points within width/2 of a polyline (round caps and joints). width > 0, >= 1 point.
PatternPtr make_strip(std::vector<Vec2> points, double width);
// Filled ellipse with semi-axes (a, b), rotated by `angle` (rad) about its centre.
PatternPtr make_ellipse(Vec2 centre, double a, double b, double angle);
// Ring of the given width centred on the ellipse's outline.
PatternPtr make_ellipse_ring(Vec2 centre, double a, double b, double angle, double width);
// Bands of the given width along hyperbola branches, in the frame rotated by `angle` about
// `centre`: x^2/a^2 - y^2/b^2 = 1 (opening along x) when along_x, = -1 (along y) otherwise.
// The branches extend as far as `reach` (m) from the centre.
PatternPtr make_hyperbola(Vec2 centre, double a, double b, double angle, double width, bool along_x,
                          double reach);
// Simple polygon (even-odd rule), >= 3 vertices.
PatternPtr make_polygon(std::vector<Vec2> vertices);
// A grey raster placed on the frame: resin where the value (0 black .. 1 white) is below
// `threshold` (or at/above it when `invert`). Row 0 is the top of the image.
PatternPtr make_raster(std::vector<float> grey, int width, int height, Vec2 origin, Vec2 size,
                       double threshold, bool invert);
// The union of the parts (a single part is returned as it is).
PatternPtr make_union(std::vector<PatternPtr> parts);
// The first pattern minus all the others.
PatternPtr make_difference(std::vector<PatternPtr> parts);

// Fraction of the segment a-b inside the pattern, sampled at `samples` midpoints.
double fraction_inside(const Pattern& pattern, const Vec2& a, const Vec2& b, int samples = 16);

}  // namespace membra
