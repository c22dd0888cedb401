#pragma once
// Which triangles of a plane triangle mesh may hold a point: a uniform grid of buckets over the
// mesh's bounding box, each listing (in increasing order) the triangles whose bounding box meets
// it. A look-up then tests a handful of triangles instead of every one: an OBJ target of 100k
// faces is sampled tens of thousands of times by a design (docs/inverse_design.md).
#include <span>
#include <vector>

#include <Eigen/Core>

#include "membra/core/vec.hpp"
#include "membra/geometry/triangulation.hpp"

namespace membra {

class TriangleLocator {
 public:
  // xy: the vertices' plane coordinates; about two triangles per bucket. Where buckets would not
  // pay (coordinates that are not finite, or slivers that span much of the mesh), every triangle
  // is a candidate everywhere.
  TriangleLocator(const Eigen::Matrix2Xd& xy, const std::vector<Triangle>& triangles);

  // Every triangle that holds p, or lies within 1e-6 of the mesh's extent of it (the buckets'
  // margin, far wider than the callers' tolerance), and others near it, in increasing index
  // order; none when p lies outside the mesh's bounding box.
  std::span<const int> candidates(const Vec2& p) const;

 private:
  Vec2 lo_ = Vec2::Zero(), cell_ = Vec2::Ones();
  int nx_ = 0, ny_ = 0;
  bool scan_all_ = false;
  std::vector<int> start_, items_;  // bucket b holds items_[start_[b]] .. items_[start_[b + 1] - 1]
};

}  // namespace membra
