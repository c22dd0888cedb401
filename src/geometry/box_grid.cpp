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
  if (!std::isfinite(span)) {
    // Boxes farther apart than a double spans: one cell holds them all (no index to compute).
    one_cell_ = true;
    cell_ = span;  // infinite: one cell
    top_.setZero();
    for (size_t b = 0; b < boxes_.size(); ++b)
      if (!boxes_[b].isEmpty()) entries_.emplace_back(0, static_cast<int>(b));
    return;
  }
  if (!(cell > 0.0) || !std::isfinite(cell)) cell = span;
  // Indices fit a key's 21 bits per axis.
  cell_ = std::max({cell, span / 2.0e6, 1e-12});
  top_ = index(all.max());
  double met = cells_met();
  while (met > 16.0 * static_cast<double>(boxes_.size()) + 1e6) {
    cell_ *= 2.0;
    top_ = index(all.max());
    met = cells_met();
  }
  entries_.reserve(static_cast<size_t>(met));
  for (size_t b = 0; b < boxes_.size(); ++b) {
    Eigen::Array3i c0, c1;
    if (!cell_range(boxes_[b], c0, c1)) continue;
    for_each_cell(c0, c1, [&](std::uint64_t k) { entries_.emplace_back(k, static_cast<int>(b)); });
  }
  std::sort(entries_.begin(), entries_.end());
}

double BoxGrid::mean_size(const std::vector<Eigen::AlignedBox3d>& boxes) {
  double sum = 0.0;
  int n = 0;
  for (const auto& b : boxes)
    if (!b.isEmpty() && b.min().allFinite() && b.max().allFinite()) {
      sum += b.sizes().maxCoeff();
      ++n;
    }
  return n == 0 ? 0.0 : sum / n;
}

bool BoxGrid::cell_range(const Eigen::AlignedBox3d& b, Eigen::Array3i& c0,
                         Eigen::Array3i& c1) const {
  if (b.isEmpty() || top_.x() < 0) return false;
  if (one_cell_) {
    if (b.min().array().isNaN().any() || b.max().array().isNaN().any()) return false;
    c0 = c1 = Eigen::Array3i::Zero();
    return true;
  }
  // In doubles first: a query far outside the grid would overflow an int.
  const Eigen::Array3d f0 = ((b.min() - lo_) / cell_).array().floor(),
                       f1 = ((b.max() - lo_) / cell_).array().floor();
  const Eigen::Array3d top = top_.cast<double>();
  if (f0.isNaN().any() || f1.isNaN().any() || (f1 < 0.0).any() || (f0 > top).any()) return false;
  c0 = f0.max(0.0).cast<int>();
  c1 = f1.min(top).cast<int>();
  return true;
}

double BoxGrid::cells_met() const {
  double sum = 0.0;
  for (const auto& b : boxes_) {
    Eigen::Array3i c0, c1;
    if (cell_range(b, c0, c1)) sum += ((c1 - c0).cast<double>() + 1.0).prod();
  }
  return sum;
}

}  // namespace membra
