#pragma once
// A uniform grid of cubic cells over axis-aligned boxes in space: each box is listed in every cell
// it meets, the list sorted by cell. The broad phase of the self-intersection check (pairs of
// triangles that may cross) and of self-contact (triangles a point may come near), so that their
// cost grows with the number of boxes, not its square.
#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "membra/core/vec.hpp"
#include "membra/geometry/triangulation.hpp"

namespace membra {

// The box of triangle t at positions x (3 x N), grown by `pad` on every side: what both users of
// the grid list.
inline Eigen::AlignedBox3d triangle_box(const Points& x, const Triangle& t, double pad = 0.0) {
  Eigen::AlignedBox3d b(x.col(t[0]));
  b.extend(Vec3(x.col(t[1])));
  b.extend(Vec3(x.col(t[2])));
  return Eigen::AlignedBox3d(b.min().array() - pad, b.max().array() + pad);
}

class BoxGrid {
 public:
  // Cells `cell` across (callers pass about a box's size: few cells per box, few boxes per cell),
  // made coarser where needed: at most 2^21 cells along an axis, and no more cells met than 16
  // per box plus a million (a few huge boxes, a sheet torn into long slivers, would otherwise
  // span millions each). A box with a coordinate that is not finite is in no cell; boxes farther
  // apart than a double spans share one cell.
  BoxGrid(std::vector<Eigen::AlignedBox3d> boxes, double cell);

  const Eigen::AlignedBox3d& box(int b) const { return boxes_[static_cast<size_t>(b)]; }
  double cell() const { return cell_; }

  // The mean of the largest sides of the boxes that are finite and not empty (zero for none;
  // infinite if a side overflows, which the constructor treats as no size given): the callers'
  // usual cell size.
  static double mean_size(const std::vector<Eigen::AlignedBox3d>& boxes);

  // Calls f(b) for every box b that shares a cell with `query` (a box may come more than once,
  // and boxes that do not meet `query` may come too: the caller tests what it needs).
  template <typename F>
  void overlapping(const Eigen::AlignedBox3d& query, F&& f) const {
    Eigen::Array3i c0, c1;
    if (!cell_range(query, c0, c1)) return;
    for_each_cell(c0, c1, [&](std::uint64_t key) {
      auto it = std::lower_bound(entries_.begin(), entries_.end(), std::pair{key, -1});
      for (; it != entries_.end() && it->first == key; ++it) f(it->second);
    });
  }

  // Calls f(a, b), a listed before b, once for each pair of boxes that meet: in the cell that
  // holds the low corner of their overlap.
  template <typename F>
  void overlapping_pairs(F&& f) const {
    for (size_t first = 0; first < entries_.size();) {
      size_t end = first;
      while (end < entries_.size() && entries_[end].first == entries_[first].first) ++end;
      for (size_t m = first; m < end; ++m)
        for (size_t n = m + 1; n < end; ++n) {
          const int a = entries_[m].second, b = entries_[n].second;
          if (tested_here(a, b, entries_[first].first)) f(a, b);
        }
      first = end;
    }
  }

 private:
  // Inline, as is tested_here: both run for every candidate pair.
  Eigen::Array3i index(const Vec3& p) const {
    if (one_cell_) return Eigen::Array3i::Zero();
    return ((p - lo_) / cell_).array().floor().cast<int>().eval();
  }
  // The cells a box meets, clipped to the grid; false when it meets none.
  bool cell_range(const Eigen::AlignedBox3d& b, Eigen::Array3i& c0, Eigen::Array3i& c1) const;
  static std::uint64_t key(int i, int j, int k) {
    return static_cast<std::uint64_t>(i) << 42 | static_cast<std::uint64_t>(j) << 21 |
           static_cast<std::uint64_t>(k);
  }
  template <typename F>
  static void for_each_cell(const Eigen::Array3i& c0, const Eigen::Array3i& c1, F&& f) {
    for (int i = c0.x(); i <= c1.x(); ++i)
      for (int j = c0.y(); j <= c1.y(); ++j)
        for (int k = c0.z(); k <= c1.z(); ++k) f(key(i, j, k));
  }
  double cells_met() const;
  bool tested_here(int a, int b, std::uint64_t cell_key) const {
    const Eigen::AlignedBox3d& ba = box(a);
    const Eigen::AlignedBox3d& bb = box(b);
    if (!ba.intersects(bb)) return false;
    const Eigen::Array3i c = index(ba.min().cwiseMax(bb.min()));
    return key(c.x(), c.y(), c.z()) == cell_key;
  }

  std::vector<Eigen::AlignedBox3d> boxes_;
  Vec3 lo_ = Vec3::Zero();
  Eigen::Array3i top_ = Eigen::Array3i::Constant(-1);  // the highest cell index along each axis
  double cell_ = 1.0;
  bool one_cell_ = false;
  std::vector<std::pair<std::uint64_t, int>> entries_;  // (cell, box), sorted
};

}  // namespace membra
