#pragma once
// A conformal flattening of a triangle mesh by least-squares conformal maps (LSCM): the plane
// coordinates (u, v) whose map to the surface is as close to a similarity as possible on every
// triangle, so the surface's metric is the plane's times one scale factor per point — the
// isotropic shrink a resin density can give. Two vertices are pinned at their own (x, y) (the
// farthest apart of the footprint), so the flattening keeps the footprint's orientation; its
// boundary is free. Used by inverse design's first stage (design/target_correspondence.hpp).
#include <vector>

#include <Eigen/Core>

#include "membra/core/vec.hpp"
#include "membra/geometry/triangulation.hpp"

namespace membra {

// (u, v) per vertex, m. Throws std::invalid_argument for a mesh without faces.
Eigen::Matrix2Xd conformal_flattening(const Points& x, const std::vector<Triangle>& triangles);

}  // namespace membra
