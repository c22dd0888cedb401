#pragma once
// Summaries of a form: how far it rises out of its best-fit plane, its bounding box.
#include "membra/geometry/vec.hpp"

namespace membra {

struct ShapeSummary {
  double height = 0.0;   // extent along the normal of the least-squares plane, m
  double z_range = 0.0;  // max z - min z, m
  Vec3 bbox_min = Vec3::Zero(), bbox_max = Vec3::Zero();  // m
  Vec3 normal = Vec3::UnitZ();  // normal of the least-squares plane (smallest principal axis)
};

// Shape summary of a point set (3 x N, N >= 1). The best-fit plane makes `height` independent of
// how the released sheet happens to lie in space.
ShapeSummary summarize_shape(const Points& x);

}  // namespace membra
