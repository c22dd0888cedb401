#pragma once
// The stress on the edge of a round hole, read from the field off the edge. A grid hole is a
// staircase whose flat runs under-read the edge (about 0.78x) and whose corners over-read it,
// while a couple of spacings in the field is the smooth hole's (docs/deformation.md). Like the
// hot-spot method of weld fatigue, which extrapolates the stress to a weld toe from reference
// points off it, the edge value is extrapolated along rays from the hole's centre: along a ray
// the stress around a round hole in a uniform far field is a quadratic in u = R^2/r^2 (Kirsch),
// so a least-squares quadratic in u through samples 3 to 8 spacings off the circle, evaluated at
// u = 1, gives the edge.
#include <optional>
#include <vector>

#include "membra/core/vec.hpp"
#include "membra/geometry/grid_sheet.hpp"

namespace membra {

// A per-particle field at paper point p (m), bilinear in the grid cell around p; nothing when a
// corner of that cell is not a particle.
std::optional<double> sample_field(const GridSheet& grid, const std::vector<double>& field,
                                   const Vec2& p);

// The field extrapolated to the circle (centre, radius; paper, m) along the unit `direction`;
// nothing when a sample point is off the sheet or in another hole.
std::optional<double> edge_value(const GridSheet& grid, const std::vector<double>& field,
                                 const Vec2& centre, double radius, const Vec2& direction);

struct HoleEdge {
  bool valid = false;          // some ray could be extrapolated
  Vec2 centre = Vec2::Zero();  // of the removed particles, paper m
  double radius = 0.0;         // of the circle with the hole's area, m
  double value = 0.0;          // the largest edge value over the rays
  double angle = 0.0;          // rad, direction of that ray from +x
};

// Holes smaller than this many spacings (radius) are not extrapolated.
constexpr double kMinHoleRadius = 6.0;

// The hole that removed the particles at paper positions `removed`, seen as the circle with its
// area: the largest edge value of `field` over `rays` directions. Not valid for a hole of radius
// below kMinHoleRadius spacings, or when no ray has its samples on the sheet.
HoleEdge hole_edge(const GridSheet& grid, const std::vector<double>& field,
                   const std::vector<Vec2>& removed, int rays = 72);

}  // namespace membra
