#include "membra/measure/self_intersection.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "membra/core/units.hpp"
#include "membra/geometry/box_grid.hpp"

namespace membra {
namespace {

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
  // Cells about twice a mean triangle across.
  std::vector<Eigen::AlignedBox3d> boxes;
  boxes.reserve(tris.size());
  for (const Triangle& t : tris) boxes.push_back(triangle_box(x, t));
  const double cell = 2.0 * BoxGrid::mean_size(boxes);
  const BoxGrid grid(std::move(boxes), cell);
  std::vector<int> crossing;
  grid.overlapping_pairs([&](int s, int t) {
    if (!pair_crosses(x, tris[static_cast<size_t>(s)], tris[static_cast<size_t>(t)])) return;
    ++out.pairs;
    crossing.push_back(s), crossing.push_back(t);
  });
  std::sort(crossing.begin(), crossing.end());
  crossing.erase(std::unique(crossing.begin(), crossing.end()), crossing.end());
  out.at = nearest_to_mean(x, tris, crossing);
  out.triangles = std::move(crossing);
  return out;
}

std::string crossing_summary(const SelfIntersection& si) {
  char at[96];
  // Rounded first, then + 0.0: no "-0" for a coordinate just below zero.
  const auto mm = [](double v) { return std::round(v / units::mm) + 0.0; };
  std::snprintf(at, sizeof at, "(%.0f, %.0f, %.0f) mm", mm(si.at.x()), mm(si.at.y()),
                mm(si.at.z()));
  return std::to_string(si.pairs) + " pairs of triangles cross, around " + at;
}

}  // namespace membra
