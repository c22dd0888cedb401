#pragma once
// The surfaces inverse design aims at: analytic patches (spherical cap, saddle, cylinder, a
// height-field formula) or an OBJ mesh, as a triangle mesh centred on the origin, z up.
#include <memory>
#include <string>
#include <vector>

#include "membra/core/vec.hpp"
#include "membra/geometry/triangle_locator.hpp"
#include "membra/geometry/triangulation.hpp"

namespace membra {

struct TargetSpec {
  std::string kind = "cap";  // cap | saddle | cylinder | height_field | obj
  double size = 0.15;        // m: footprint diameter (cap) or side (the others)
  double height = 0.0225;    // m: the patch's rise (cap, saddle: corners to centre, cylinder)
  std::string formula;       // height_field: z(x, y) in mm, x and y in mm from the centre
  std::string obj_file;      // obj: where the mesh came from (for messages)
  Points obj_x;              // obj: the mesh's vertices, m (read by io/obj.hpp)
  std::vector<Triangle> obj_triangles;
  int resolution = 41;  // vertices along the side of the analytic patches
};

struct TargetSurface {
  std::string kind;
  Points x;  // m, centred: the footprint's centre at the origin, the lowest point at z = 0
  std::vector<Triangle> triangles;
  bool disk = false;      // the footprint is a disk (else a square, or the OBJ's own)
  double diameter = 0.0;  // m: the error's unit: cap diameter, square side, OBJ's larger extent
  double area = 0.0;      // m^2, of the surface
  // Which triangles hold a footprint point (make_target builds it; without one, look-ups scan
  // every triangle).
  std::shared_ptr<const TriangleLocator> locator;
};

// Builds the target. Throws std::invalid_argument naming what is wrong (a cap higher than its
// radius, a formula that does not parse, an OBJ mesh without faces).
TargetSurface make_target(const TargetSpec& spec);

// Area of a triangle mesh, m^2.
double mesh_area(const Points& x, const std::vector<Triangle>& triangles);

}  // namespace membra
