#pragma once
// The edges of a closed polygon bucketed on a uniform grid over its bounding box, so that the
// even-odd test and the distance to the outline look at the edges near the point, not at all of
// them: a stencil traced from CAD may have 10^5 vertices and is queried hundreds of thousands of
// times when its outline is traced at 0.25 mm (docs/errors.md, hostile scenes).
#include <limits>
#include <vector>

#include "membra/core/vec.hpp"
#include "membra/model/pattern.hpp"  // Box2

namespace membra {

class PolygonIndex {
 public:
  explicit PolygonIndex(std::vector<Vec2> vertices);
  // Even-odd rule, as the plain loop over every edge.
  bool contains(const Vec2& p) const;
  // Distance from p to the nearest edge. With `extra_rings`, the search stops that many rings of
  // cells after the first that holds an edge: exact within that many cells of the outline, an
  // upper bound beyond (never below the distance to the box) — what tracing an outline needs,
  // without searching a large polygon's empty middle.
  double distance(const Vec2& p, int extra_rings = std::numeric_limits<int>::max()) const;
  const Box2& bounds() const { return box_; }
  const std::vector<Vec2>& vertices() const { return v_; }

 private:
  int column(double x) const;
  int row(double y) const;
  // Squared distance from p to the nearest edge listed in cell (i, j).
  double cell_distance2(const Vec2& p, int i, int j) const;

  std::vector<Vec2> v_;  // edge e runs from v_[e - 1] (cyclic) to v_[e]
  Box2 box_;
  // Records edge e in the cells it passes through: for each row it spans, the columns of the
  // part of the edge inside that row's band (an edge across the whole polygon occupies a line
  // of cells, not its bounding box).
  void add_edge(int e, const Vec2& a, const Vec2& b);

  double cell_ = 1.0;                    // square cells, sized by the box's longer side
  int nx_ = 1, ny_ = 1;                  // cells along x and y
  std::vector<std::vector<int>> rows_;   // edges whose y-range meets each row
  std::vector<std::vector<int>> cells_;  // edges passing through each cell, row-major
  std::vector<int> empty_rings_;         // per cell: rings around it (Chebyshev) without any edge
};

}  // namespace membra
