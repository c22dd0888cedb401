#include "membra/measure/self_intersection.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace membra {
namespace {

struct Box {
  Vec3 lo, hi;
};

// Whether the open segment p-q passes through the triangle a, b, c (Moller-Trumbore); a segment
// in the triangle's plane does not count.
bool segment_crosses(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a, d = q - p;
  const Vec3 h = d.cross(e2);
  const double det = e1.dot(h);
  if (std::abs(det) <= 1e-12 * e1.norm() * e2.norm() * d.norm()) return false;
  const double f = 1.0 / det;
  const Vec3 s = p - a;
  const double u = f * s.dot(h);
  if (u < 0.0 || u > 1.0) return false;
  const Vec3 r = s.cross(e1);
  const double v = f * d.dot(r);
  if (v < 0.0 || u + v > 1.0) return false;
  const double t = f * e2.dot(r);
  return t > 0.0 && t < 1.0;
}

bool triangles_cross(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b) {
  for (int k = 0; k < 3; ++k)
    if (segment_crosses(a[k], a[(k + 1) % 3], b[0], b[1], b[2]) ||
        segment_crosses(b[k], b[(k + 1) % 3], a[0], a[1], a[2]))
      return true;
  return false;
}

bool share_a_vertex(const Triangle& s, const Triangle& t) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (s[i] == t[j]) return true;
  return false;
}

// A cell's key: its three indices, 21 bits each.
uint64_t cell_key(const Eigen::Array3i& c) {
  return static_cast<uint64_t>(c.x()) << 42 | static_cast<uint64_t>(c.y()) << 21 |
         static_cast<uint64_t>(c.z());
}

// The triangles' boxes on a uniform grid of cells about twice a mean triangle across (and at
// most 2^21 along an axis): `entries` holds (cell, triangle) for every cell a box meets, sorted.
struct CellGrid {
  std::vector<Box> box;
  Vec3 lo = Vec3::Zero();
  double cell = 1.0;
  std::vector<std::pair<uint64_t, int>> entries;

  Eigen::Array3i index(const Vec3& p) const {
    return ((p - lo) / cell).array().floor().cast<int>().eval();
  }

  CellGrid(const Points& x, const std::vector<Triangle>& tris) : box(tris.size()) {
    lo = x.col(tris[0][0]);
    Vec3 hi = lo;
    double extent = 0.0;
    for (size_t t = 0; t < tris.size(); ++t) {
      const Vec3 a = x.col(tris[t][0]), b = x.col(tris[t][1]), c = x.col(tris[t][2]);
      box[t] = {a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c)};
      lo = lo.cwiseMin(box[t].lo), hi = hi.cwiseMax(box[t].hi);
      extent += (box[t].hi - box[t].lo).maxCoeff();
    }
    // At most 2e6 cells along an axis, so that an index fits the key's 21 bits.
    cell = std::max(
        {2.0 * extent / static_cast<double>(tris.size()), (hi - lo).maxCoeff() / 2.0e6, 1e-12});
    // A few huge triangles (a sheet torn into long slivers) could span millions of cells each:
    // coarser cells until every box's cells add up to a few per triangle.
    while (cells_needed() > 16 * tris.size() + 1'000'000) cell *= 2.0;
    for (size_t t = 0; t < tris.size(); ++t) {
      const Eigen::Array3i c0 = index(box[t].lo), c1 = index(box[t].hi);
      for (int i = c0.x(); i <= c1.x(); ++i)
        for (int j = c0.y(); j <= c1.y(); ++j)
          for (int k = c0.z(); k <= c1.z(); ++k)
            entries.emplace_back(cell_key({i, j, k}), static_cast<int>(t));
    }
    std::sort(entries.begin(), entries.end());
  }

  size_t cells_needed() const {
    double sum = 0.0;
    for (const Box& b : box) sum += ((index(b.hi) - index(b.lo)).cast<double>() + 1.0).prod();
    return static_cast<size_t>(std::min(sum, 1e18));
  }

  // Whether the boxes of s and t meet and the cell `key` is where their pair is tested: the one
  // holding the low corner of their overlap, so that each pair is tested once.
  bool tested_here(int s, int t, uint64_t key) const {
    const Box& bs = box[static_cast<size_t>(s)];
    const Box& bt = box[static_cast<size_t>(t)];
    if ((bs.lo.array() > bt.hi.array()).any() || (bt.lo.array() > bs.hi.array()).any())
      return false;
    return cell_key(index(bs.lo.cwiseMax(bt.lo))) == key;
  }
};

bool pair_crosses(const Points& x, const Triangle& s, const Triangle& t) {
  if (share_a_vertex(s, t)) return false;
  return triangles_cross({x.col(s[0]), x.col(s[1]), x.col(s[2])},
                         {x.col(t[0]), x.col(t[1]), x.col(t[2])});
}

// The centroid of the listed triangle nearest the mean of their centroids: a place on the
// sheet even when it crosses itself in two places (the mean alone could lie between them).
Vec3 nearest_to_mean(const Points& x, const std::vector<Triangle>& tris,
                     const std::vector<int>& listed) {
  if (listed.empty()) return Vec3::Zero();
  std::vector<Vec3> centroid;
  Vec3 mean = Vec3::Zero();
  for (int t : listed) {
    const Triangle& tri = tris[static_cast<size_t>(t)];
    centroid.push_back((x.col(tri[0]) + x.col(tri[1]) + x.col(tri[2])) / 3.0);
    mean += centroid.back() / static_cast<double>(listed.size());
  }
  return *std::min_element(centroid.begin(), centroid.end(), [&](const Vec3& a, const Vec3& b) {
    return (a - mean).squaredNorm() < (b - mean).squaredNorm();
  });
}

}  // namespace

SelfIntersection self_intersections(const Points& x, const std::vector<Triangle>& tris) {
  SelfIntersection out;
  if (tris.size() < 2 || !x.allFinite()) return out;
  const CellGrid grid(x, tris);
  const auto& entries = grid.entries;
  std::vector<int> crossing;
  for (size_t first = 0; first < entries.size();) {
    size_t end = first;
    while (end < entries.size() && entries[end].first == entries[first].first) ++end;
    for (size_t m = first; m < end; ++m)
      for (size_t n = m + 1; n < end; ++n) {
        const int s = entries[m].second, t = entries[n].second;
        if (!grid.tested_here(s, t, entries[first].first) ||
            !pair_crosses(x, tris[static_cast<size_t>(s)], tris[static_cast<size_t>(t)]))
          continue;
        ++out.pairs;
        crossing.push_back(s), crossing.push_back(t);
      }
    first = end;
  }
  std::sort(crossing.begin(), crossing.end());
  crossing.erase(std::unique(crossing.begin(), crossing.end()), crossing.end());
  out.at = nearest_to_mean(x, tris, crossing);
  out.triangles = std::move(crossing);
  return out;
}

}  // namespace membra
