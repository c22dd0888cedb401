#pragma once
// A regular rectangular grid of nodes covering a flat sheet, with a mask that removes nodes
// (outlines, holes). Coordinates are "paper coordinates" of the natural, unstretched sheet in
// metres: x in [0, width], y in [0, height], origin at the lower-left corner.
#include <functional>
#include <vector>

#include "membra/core/vec.hpp"

namespace membra {

// Size and resolution of a grid sheet.
struct GridSpec {
  double width = 0.2;   // m, along x
  double height = 0.2;  // m, along y
  int nx = 41;          // nodes along x (>= 2)
  int ny = 41;          // nodes along y (>= 2)
};

// Decides whether the node at paper position (x, y) [m] belongs to the sheet.
using NodeMask = std::function<bool(double x, double y)>;

// The grid and the map between grid nodes (i, j) and the particles that survive the mask.
class GridSheet {
 public:
  // Builds the grid; nodes for which `keep` returns false are masked out. Throws
  // std::invalid_argument for a non-positive size or fewer than 2 nodes per side.
  // An empty grid (no nodes), to be assigned later.
  GridSheet() = default;
  explicit GridSheet(const GridSpec& spec, const NodeMask& keep = {});
  // Builds the grid keeping node (i, j) where keep_node[j * nx + i] is true.
  GridSheet(const GridSpec& spec, const std::vector<bool>& keep_node);

  // A copy without the nodes that belong to no active cell (they would carry no mass).
  GridSheet without_isolated_nodes() const;

  int nx() const { return spec_.nx; }
  int ny() const { return spec_.ny; }
  double width() const { return spec_.width; }
  double height() const { return spec_.height; }
  double hx() const { return spec_.width / (spec_.nx - 1); }   // node spacing along x (m)
  double hy() const { return spec_.height / (spec_.ny - 1); }  // node spacing along y (m)

  // Particle index of node (i, j), or -1 when masked or outside the grid.
  int particle(int i, int j) const;
  // Grid node (i, j) of particle p.
  std::pair<int, int> node(int p) const { return node_of_particle_[p]; }
  // Paper position (m) of node (i, j).
  Vec2 position(int i, int j) const { return {i * hx(), j * hy()}; }
  int num_particles() const { return static_cast<int>(node_of_particle_.size()); }
  // True when all four corners of cell (i, j)-(i+1, j+1) are particles.
  bool cell_active(int i, int j) const;

 private:
  void check_spec() const;
  void index_nodes(const std::vector<bool>& keep_node);

  GridSpec spec_;
  std::vector<int> particle_of_node_;
  std::vector<std::pair<int, int>> node_of_particle_;
};

}  // namespace membra
