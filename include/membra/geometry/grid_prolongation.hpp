#pragma once
// Positions carried from a coarse grid sheet to a finer one over the same paper: each fine node
// takes the bilinear interpolation of the coarse nodes around its paper position. Where the
// coarse grid lacks some of those nodes (an outline, a hole), the present ones share the weight;
// where it lacks all four, the nearest coarse particle stands in. Multilevel release
// (process/multilevel.hpp) starts each finer grid from the coarser grid's form this way.
#include "membra/core/vec.hpp"
#include "membra/geometry/grid_sheet.hpp"

namespace membra {

// `coarse_x`: a position per particle of `coarse`; the result has one per particle of `fine`.
// Both sheets must cover the same paper (width, height). Throws std::invalid_argument otherwise,
// or when the coarse sheet has no particle.
Points prolongate(const GridSheet& coarse, const Points& coarse_x, const GridSheet& fine);

}  // namespace membra
