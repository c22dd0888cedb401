#include "membra/geometry/triangle_locator.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace membra {

TriangleLocator::TriangleLocator(const Eigen::Matrix2Xd& xy,
                                 const std::vector<Triangle>& triangles) {
  if (triangles.empty() || xy.cols() == 0) return;
  const size_t count = triangles.size();
  const Vec2 lo = xy.rowwise().minCoeff(), hi = xy.rowwise().maxCoeff();
  // A margin well beyond the 1e-9 (barycentric) by which the callers let a point stand outside.
  const double margin = 1e-6 * std::max((hi - lo).maxCoeff(), 1e-300);
  lo_ = lo - Vec2::Constant(margin);
  const Vec2 extent = (hi - lo) + Vec2::Constant(2.0 * margin);
  nx_ = ny_ = std::max(1, static_cast<int>(std::sqrt(0.5 * static_cast<double>(count))));
  cell_ = extent / nx_;
  // Each triangle's range of buckets.
  const auto bucket_range = [&](const Triangle& t) {
    Vec2 a = xy.col(t[0]), b = a;
    for (int k = 1; k < 3; ++k) a = a.cwiseMin(xy.col(t[k])), b = b.cwiseMax(xy.col(t[k]));
    const auto at = [&](double v, double from, double step, int n) {
      return std::clamp(static_cast<int>(std::floor((v - from) / step)), 0, n - 1);
    };
    return std::array<int, 4>{
        at(a.x() - margin, lo_.x(), cell_.x(), nx_), at(b.x() + margin, lo_.x(), cell_.x(), nx_),
        at(a.y() - margin, lo_.y(), cell_.y(), ny_), at(b.y() + margin, lo_.y(), cell_.y(), ny_)};
  };
  size_t entries = 0;
  if (xy.allFinite())
    for (const Triangle& t : triangles) {
      const auto r = bucket_range(t);
      entries += static_cast<size_t>(r[1] - r[0] + 1) * static_cast<size_t>(r[3] - r[2] + 1);
    }
  // Coordinates that are not finite, or slivers spanning much of the mesh (a large polygon's fan)
  // that would fill the buckets many times over: one bucket with every triangle, a plain scan.
  if (!xy.allFinite() || entries > 32 * count) {
    nx_ = ny_ = 1;
    cell_ = extent;
    scan_all_ = true;
    start_ = {0, static_cast<int>(count)};
    items_.resize(count);
    for (size_t k = 0; k < count; ++k) items_[k] = static_cast<int>(k);
    return;
  }
  // A counting sort into the buckets, in index order.
  start_.assign(static_cast<size_t>(nx_) * static_cast<size_t>(ny_) + 1, 0);
  for (const Triangle& t : triangles) {
    const auto r = bucket_range(t);
    for (int j = r[2]; j <= r[3]; ++j)
      for (int i = r[0]; i <= r[1]; ++i) ++start_[static_cast<size_t>(j * nx_ + i) + 1];
  }
  for (size_t b = 1; b < start_.size(); ++b) start_[b] += start_[b - 1];
  items_.resize(static_cast<size_t>(start_.back()));
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (int k = 0; k < static_cast<int>(count); ++k) {
    const auto r = bucket_range(triangles[static_cast<size_t>(k)]);
    for (int j = r[2]; j <= r[3]; ++j)
      for (int i = r[0]; i <= r[1]; ++i) items_[static_cast<size_t>(fill[j * nx_ + i]++)] = k;
  }
}

std::span<const int> TriangleLocator::candidates(const Vec2& p) const {
  if (nx_ == 0) return {};
  if (scan_all_ && !lo_.allFinite()) return items_;  // a mesh without a finite bounding box
  const Vec2 u = (p - lo_).cwiseQuotient(cell_);
  if (!(u.x() >= 0.0 && u.y() >= 0.0 && u.x() <= nx_ && u.y() <= ny_)) return {};
  if (scan_all_) return items_;
  const int i = std::min(static_cast<int>(u.x()), nx_ - 1),
            j = std::min(static_cast<int>(u.y()), ny_ - 1);
  const size_t b = static_cast<size_t>(j * nx_ + i);
  return {items_.data() + start_[b], items_.data() + start_[b + 1]};
}

}  // namespace membra
