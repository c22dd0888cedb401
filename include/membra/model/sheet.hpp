#pragma once
// A membrane sheet: the grid, its triangles and the particle-spring model built on it.
#include <optional>
#include <vector>

#include "membra/geometry/grid_sheet.hpp"
#include "membra/geometry/size_field.hpp"
#include "membra/geometry/triangulation.hpp"
#include "membra/model/material.hpp"
#include "membra/model/model.hpp"

namespace membra {

// How to build the lattice.
struct SheetOptions {
  Material material = latex();
  bool stretch = true;      // grid-edge springs
  bool shear = true;        // both diagonals of each cell
  bool flex = false;        // skip-one springs (the paper's "bend"; no linear bending stiffness)
  bool bending = true;      // plate bending with D = E t^3 / (12 (1 - nu^2)), see bending.hpp
  double flex_ratio = 0.1;  // k_flex / k_stretch when flex is on
  std::optional<double> stretch_stiffness;  // overrides k_stretch (N/m): the paper's K
  double spring_damping = 0.0;              // c of every spring, N*s/m
};

// How a continuum sheet's mesh is made (continuum_sheet.hpp): the scene's "sheet.mesh".
struct MeshSpec {
  double max_edge = 0.0;    // m, the size away from boundaries; 0: the sheet's smaller side / 20
  int elements_across = 4;  // elements across the narrowest resin piece or latex gap
  double min_angle_deg = 25.0;
  double grading = 0.3;     // growth of the element size per unit distance from a boundary
  double tolerance = 2e-5;  // m, chords of curved outlines (ellipses, disks, round caps)
};

// The continuum sheet's mesh as made (empty on a lattice): what report.json's "mesh" says, and
// the rim the frame holds.
struct SheetMesh {
  MeshSpec spec;  // as asked, max_edge resolved
  int vertices = 0, triangles = 0;
  double min_angle_deg = 0.0, min_edge = 0.0, mean_edge = 0.0;  // deg, m, m
  NarrowestFeature narrowest;    // the narrowest piece or gap the size field found
  std::vector<int> rim;          // particles on the sheet's outline ...
  std::vector<Vec2> rim_normal;  // ... and its outward normal there (natural sheet)
};

struct Sheet {
  GridSheet grid;     // the lattice's grid; empty on a continuum sheet
  Material material;  // of the sheet (latex)
  Model model;
  std::vector<Triangle> triangles;
  LatticeStiffness stiffness;  // N/m per family, as built
  SheetOptions options;        // how it was built (to rebuild it when holes remove nodes)
  SheetMesh mesh;              // the continuum sheet's mesh; empty on a lattice

  bool continuum() const { return mesh.triangles > 0; }
};

// c / D of the bending element centred on node (i, j) along grid direction (di, dj), for cells
// of hx x hy (the grid's own, or the stretched ones where resin sets): the plate weights
// (bending.hpp) times the node's area, 0 where the element does not exist.
double bending_factor(const GridSheet& g, int i, int j, int di, int dj, double hx, double hy);

// Builds the sheet: lumped masses (area x thickness x density, a quarter of each active cell to
// each of its corners), the chosen spring families at rest in the flat grid, bending elements
// (unless switched off), no pins, no gravity. Nodes the mask removes, and nodes left in no active
// cell, are dropped.
Sheet build_sheet(const GridSpec& spec, const SheetOptions& options, const NodeMask& keep = {});

}  // namespace membra
