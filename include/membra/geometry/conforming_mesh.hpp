#pragma once
// A triangle mesh of a planar region whose edges run along given boundaries: a constrained
// Delaunay triangulation refined to a size field and a smallest angle (CGAL's 2-D conforming
// mesher, Ruppert/Chew refinement; docs/model.md, "Meshes that follow the pattern").
#include <array>
#include <functional>
#include <vector>

#include "membra/core/vec.hpp"

namespace membra {

struct PlanarMesh {
  std::vector<Vec2> vertices;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise

  double min_angle_deg() const;  // the smallest angle of any triangle
  double min_edge() const;       // the shortest edge, m
  double max_edge() const;       // the longest edge, m
};

struct MeshRequest {
  // The region: its outer boundary counter-clockwise; the mesh covers what it encloses.
  std::vector<Vec2> outline;
  // Closed polygons inside it whose edges the mesh must follow (resin boundaries); they may
  // touch or run along the outline.
  std::vector<std::vector<Vec2>> constraints;
  // Open polylines inside it whose edges the mesh must follow too (slits); their ends may lie on
  // the outline.
  std::vector<std::vector<Vec2>> open_constraints;
  std::function<double(const Vec2&)> size;  // the largest edge wanted at a point, m
  double min_angle_deg = 25.0;              // refinement target; <= 30 terminates in practice
  long max_vertices = 2'000'000;            // refinement stops with an error beyond it
};

// Meshes the request. Boundary edges are first split to the local size, then the triangulation
// is refined until every triangle is within its size and angle. Throws std::invalid_argument for
// an outline of fewer than 3 points, and std::runtime_error when the mesh would exceed
// max_vertices.
PlanarMesh conforming_mesh(const MeshRequest& request);

}  // namespace membra
