#include "membra/geometry/grid_sheet.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace membra {

void GridSheet::check_spec() const {
  if (!(spec_.width > 0.0) || !(spec_.height > 0.0) || !std::isfinite(spec_.width) ||
      !std::isfinite(spec_.height)) {
    throw std::invalid_argument("grid sheet: width and height must be positive and finite");
  }
  if (spec_.nx < 2 || spec_.ny < 2) {
    throw std::invalid_argument("grid sheet: at least 2 nodes per side are needed, got " +
                                std::to_string(spec_.nx) + " x " + std::to_string(spec_.ny));
  }
}

void GridSheet::index_nodes(const std::vector<bool>& keep_node) {
  particle_of_node_.assign(static_cast<size_t>(spec_.nx) * spec_.ny, -1);
  node_of_particle_.clear();
  for (int j = 0; j < spec_.ny; ++j) {
    for (int i = 0; i < spec_.nx; ++i) {
      const size_t n = static_cast<size_t>(j) * spec_.nx + i;
      if (!keep_node[n]) continue;
      particle_of_node_[n] = static_cast<int>(node_of_particle_.size());
      node_of_particle_.emplace_back(i, j);
    }
  }
}

GridSheet::GridSheet(const GridSpec& spec, const NodeMask& keep) : spec_(spec) {
  check_spec();
  std::vector<bool> keep_node(static_cast<size_t>(spec.nx) * spec.ny, true);
  if (keep) {
    for (int j = 0; j < spec.ny; ++j)
      for (int i = 0; i < spec.nx; ++i) {
        const Vec2 p = position(i, j);
        keep_node[static_cast<size_t>(j) * spec.nx + i] = keep(p.x(), p.y());
      }
  }
  index_nodes(keep_node);
}

GridSheet::GridSheet(const GridSpec& spec, const std::vector<bool>& keep_node) : spec_(spec) {
  check_spec();
  if (keep_node.size() != static_cast<size_t>(spec.nx) * spec.ny)
    throw std::invalid_argument("grid sheet: node mask has the wrong size");
  index_nodes(keep_node);
}

GridSheet GridSheet::without_isolated_nodes() const {
  std::vector<bool> keep(static_cast<size_t>(spec_.nx) * spec_.ny, false);
  for (int j = 0; j + 1 < spec_.ny; ++j)
    for (int i = 0; i + 1 < spec_.nx; ++i)
      if (cell_active(i, j))
        for (int dj = 0; dj < 2; ++dj)
          for (int di = 0; di < 2; ++di)
            keep[static_cast<size_t>(j + dj) * spec_.nx + i + di] = true;
  return GridSheet(spec_, keep);
}

int GridSheet::particle(int i, int j) const {
  if (i < 0 || j < 0 || i >= spec_.nx || j >= spec_.ny) return -1;
  return particle_of_node_[static_cast<size_t>(j) * spec_.nx + i];
}

bool GridSheet::cell_active(int i, int j) const {
  return particle(i, j) >= 0 && particle(i + 1, j) >= 0 && particle(i, j + 1) >= 0 &&
         particle(i + 1, j + 1) >= 0;
}

}  // namespace membra
