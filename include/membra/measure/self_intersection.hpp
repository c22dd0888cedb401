#pragma once
// Where a form passes through itself. Neither of membra's models has self-contact: nothing stops
// one part of a released sheet from settling through another, and the solvers then report an
// equilibrium that no real sheet can take (docs/measures.md, "A form that passes through
// itself"). This finds the triangles that cross, so the run can say so.
#include <string>
#include <vector>

#include "membra/core/vec.hpp"
#include "membra/geometry/triangulation.hpp"

namespace membra {

struct SelfIntersection {
  long pairs = 0;              // pairs of triangles that share no vertex and cross
  std::vector<int> triangles;  // the triangles of those pairs, sorted, each once
  // Where they cross, m: the centroid of the crossing triangle nearest their mean (on the sheet
  // even when it crosses in two places); zero when none cross.
  Vec3 at = Vec3::Zero();
};

// The crossing triangle pairs of the surface x, tris (3 x N positions, m). Triangles sharing a
// vertex are neighbours, not crossings; coplanar overlaps (a sheet folded exactly flat onto
// itself) are not detected. Candidates come from a uniform grid of cells about twice a mean
// triangle across, so on a mesh of even size the cost grows with the number of triangles, not
// its square (a graded mesh's small triangles share cells). Positions that are not finite cross
// nothing.
SelfIntersection self_intersections(const Points& x, const std::vector<Triangle>& tris);

// "N pairs of triangles cross, around (x, y, z) mm": how many and where, for the run's warning
// and the viewer's panel alike.
std::string crossing_summary(const SelfIntersection& si);

}  // namespace membra
