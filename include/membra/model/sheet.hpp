#pragma once
// A membrane sheet: the grid, its triangles and the particle-spring model built on it.
#include <optional>
#include <vector>

#include "membra/geometry/grid_sheet.hpp"
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

struct Sheet {
  GridSheet grid;
  Material material;  // of the sheet (latex)
  Model model;
  std::vector<Triangle> triangles;
  LatticeStiffness stiffness;  // N/m per family, as built
  SheetOptions options;        // how it was built (to rebuild it when holes remove nodes)
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
