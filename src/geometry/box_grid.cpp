#include "membra/geometry/box_grid.hpp"

#include <cmath>

namespace membra {

BoxGrid::BoxGrid(std::vector<Eigen::AlignedBox3d> boxes, double cell) : boxes_(std::move(boxes)) {
  Eigen::AlignedBox3d all;  // empty
  for (auto& b : boxes_) {
    if (!b.min().allFinite() || !b.max().allFinite()) b.setEmpty();
    if (!b.isEmpty()) all.extend(b);
  }
  if (all.isEmpty()) return;
  lo_ = all.min();
  const double span = all.sizes().maxCoeff();
  if (!(cell > 0.0) || !std::isfinite(cell)) cell = span;
  // Indices fit a key's 21 bits per axis.
  cell_ = std::max({cell, span / 2.0e6, 1e-12});
  top_ = index(all.max());
  while (cells_met() > 16.0 * static_cast<double>(boxes_.size()) + 1e6) {
    cell_ *= 2.0;
    top_ = index(all.max());
  }
  for (size_t b = 0; b < boxes_.size(); ++b) {
    Eigen::Array3i c0, c1;
    if (!cell_range(boxes_[b], c0, c1)) continue;
    for_each_cell(c0, c1, [&](std::uint64_t k) { entries_.emplace_back(k, static_cast<int>(b)); });
  }
  std::sort(entries_.begin(), entries_.end());
}

double BoxGrid::mean_size(const std::vector<Eigen::AlignedBox3d>& boxes) {
  double sum = 0.0;
  for (const auto& b : boxes)
    if (!b.isEmpty()) sum += b.sizes().maxCoeff();
  return boxes.empty() ? 0.0 : sum / static_cast<double>(boxes.size());
}

Eigen::Array3i BoxGrid::index(const Vec3& p) const {
  return ((p - lo_) / cell_).array().floor().cast<int>().eval();
}

bool BoxGrid::cell_range(const Eigen::AlignedBox3d& b, Eigen::Array3i& c0,
                         Eigen::Array3i& c1) const {
  if (b.isEmpty() || top_.x() < 0) return false;
  // In doubles first: a query far outside the grid would overflow an int.
  const Eigen::Array3d f0 = ((b.min() - lo_) / cell_).array().floor(),
                       f1 = ((b.max() - lo_) / cell_).array().floor();
  const Eigen::Array3d top = top_.cast<double>();
  if (f0.isNaN().any() || f1.isNaN().any() || (f1 < 0.0).any() || (f0 > top).any()) return false;
  c0 = f0.max(0.0).cast<int>();
  c1 = f1.min(top).cast<int>();
  return true;
}

std::uint64_t BoxGrid::key(int i, int j, int k) {
  return static_cast<std::uint64_t>(i) << 42 | static_cast<std::uint64_t>(j) << 21 |
         static_cast<std::uint64_t>(k);
}

double BoxGrid::cells_met() const {
  double sum = 0.0;
  for (const auto& b : boxes_) {
    Eigen::Array3i c0, c1;
    if (cell_range(b, c0, c1)) sum += ((c1 - c0).cast<double>() + 1.0).prod();
  }
  return sum;
}

bool BoxGrid::tested_here(int a, int b, std::uint64_t cell_key) const {
  const Eigen::AlignedBox3d& ba = box(a);
  const Eigen::AlignedBox3d& bb = box(b);
  if (!ba.intersects(bb)) return false;
  const Eigen::Array3i c = index(ba.min().cwiseMax(bb.min()));
  return key(c.x(), c.y(), c.z()) == cell_key;
}

}  // namespace membra
