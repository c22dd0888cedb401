#pragma once
// The stress on the edge of a hole in the continuum sheet (docs/deformation.md, "Holes and
// slits on the continuum model"). The mesh follows the hole's outline, so the edge is the hole's
// own, not a staircase; but a triangle's stress is its mean, read about a third of its height off
// the edge, where a round hole's hoop stress falls steeply (Kirsch: from 3 s by 7 s / R per unit
// distance). So the edge value is extrapolated, as on the lattice (hole_edge.hpp): along the
// ray from the hole's centre at each angle, the triangles in a narrow wedge out to 2.5 times the
// edge's distance give a least-squares fit of the hoop stress in the terms of Kirsch's field
// near the ray (quadratic in u = (r_edge / r)^2 and in the angle off the ray), read at u = 1
// on the ray. Everything is
// measured on the paper (model.reference), the hoop direction carried to each triangle's
// current plane, so a released, curved sheet reads the same way.
#include <optional>
#include <vector>

#include "membra/core/vec.hpp"
#include "membra/measure/hole_edge.hpp"
#include "membra/model/sheet.hpp"

namespace membra {

struct MeshHole {
  std::vector<int> boundary;   // the particles around the hole, in order
  Vec2 centre = Vec2::Zero();  // paper, m: the centroid of the boundary polygon
  double radius = 0.0;         // m: the circle with the polygon's area
  double edge_length = 0.0;    // m: the boundary's mean edge
};

// The hole whose removed particles lay at paper positions `removed`: the loop of the mesh's
// boundary edges that encloses an area, touches no particle of the sheet's outline
// (sheet.mesh.rim) and whose centroid lies nearest their mean. Nothing when the sheet has no
// such loop (a hole a slit joins to the outline has none: its edge is not read).
std::optional<MeshHole> find_mesh_hole(const Sheet& sheet, const std::vector<Vec2>& removed);

// The hoop stress (Pa) at the hole's edge on the ray at `angle` (rad from +x, paper), from the
// membrane triangles' stresses at positions x; nothing when fewer than 21 triangles lie in the
// ray's wedge.
std::optional<double> mesh_edge_hoop(const Sheet& sheet, const Points& x, const MeshHole& hole,
                                     double angle);

// The largest edge value over `rays` rays, as hole_edge() reads the lattice: not valid when no
// hole is found or no ray can be fitted.
HoleEdge mesh_hole_edge(const Sheet& sheet, const Points& x, const std::vector<Vec2>& removed,
                        int rays = 72);

}  // namespace membra
