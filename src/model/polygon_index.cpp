#include "membra/model/polygon_index.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <stdexcept>

namespace membra {
namespace {

double segment_distance2(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).squaredNorm();
}

// For every cell of an n x n grid, the Chebyshev distance (in cells) to the nearest cell that
// holds an edge: a breadth-first search from those cells over the eight neighbours.
std::vector<int> chebyshev_to_nonempty(const std::vector<std::vector<int>>& cells, int n) {
  std::vector<int> dist(cells.size(), -1);
  std::deque<int> queue;
  for (size_t c = 0; c < cells.size(); ++c)
    if (!cells[c].empty()) dist[c] = 0, queue.push_back(static_cast<int>(c));
  while (!queue.empty()) {
    const int c = queue.front();
    queue.pop_front();
    const int i = c % n, j = c / n;
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int u = i + di, w = j + dj;
        if (u < 0 || w < 0 || u >= n || w >= n || dist[static_cast<size_t>(w * n + u)] >= 0)
          continue;
        dist[static_cast<size_t>(w * n + u)] = dist[static_cast<size_t>(c)] + 1;
        queue.push_back(w * n + u);
      }
  }
  return dist;
}

}  // namespace

PolygonIndex::PolygonIndex(std::vector<Vec2> vertices) : v_(std::move(vertices)) {
  if (v_.size() < 3) throw std::invalid_argument("polygon: needs at least 3 vertices");
  for (const auto& p : v_) box_.extend(p);
  const auto n = static_cast<int>(v_.size());
  // About one edge per cell along the outline; at most 512 x 512 cells.
  n_ = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(n))), 1, 512);
  cell_ = ((box_.max - box_.min) / n_).cwiseMax(1e-15);
  rows_.resize(static_cast<size_t>(n_));
  cells_.resize(static_cast<size_t>(n_) * static_cast<size_t>(n_));
  for (int e = 0; e < n; ++e) {
    const Vec2& a = v_[static_cast<size_t>((e + n - 1) % n)];
    const Vec2& b = v_[static_cast<size_t>(e)];
    const int i0 = column(std::min(a.x(), b.x())), i1 = column(std::max(a.x(), b.x()));
    const int j0 = row(std::min(a.y(), b.y())), j1 = row(std::max(a.y(), b.y()));
    for (int j = j0; j <= j1; ++j) {
      rows_[static_cast<size_t>(j)].push_back(e);
      for (int i = i0; i <= i1; ++i)
        cells_[static_cast<size_t>(j) * static_cast<size_t>(n_) + static_cast<size_t>(i)].push_back(
            e);
    }
  }
  empty_rings_ = chebyshev_to_nonempty(cells_, n_);
}

int PolygonIndex::column(double x) const {
  return std::clamp(static_cast<int>(std::floor((x - box_.min.x()) / cell_.x())), 0, n_ - 1);
}

int PolygonIndex::row(double y) const {
  return std::clamp(static_cast<int>(std::floor((y - box_.min.y()) / cell_.y())), 0, n_ - 1);
}

bool PolygonIndex::contains(const Vec2& p) const {
  if (!(p.x() >= box_.min.x() && p.x() <= box_.max.x() && p.y() >= box_.min.y() &&
        p.y() <= box_.max.y()))
    return false;
  // Every edge that the horizontal line through p crosses has p.y in its y-range, so it is
  // listed in p's row.
  const auto n = v_.size();
  bool in = false;
  for (int e : rows_[static_cast<size_t>(row(p.y()))]) {
    const Vec2& a = v_[static_cast<size_t>(e)];
    const Vec2& b = v_[(static_cast<size_t>(e) + n - 1) % n];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

double PolygonIndex::cell_distance2(const Vec2& p, int i, int j) const {
  const auto n = v_.size();
  double best = std::numeric_limits<double>::infinity();
  for (int e : cells_[static_cast<size_t>(j) * static_cast<size_t>(n_) + static_cast<size_t>(i)])
    best = std::min(best, segment_distance2(p, v_[(static_cast<size_t>(e) + n - 1) % n],
                                            v_[static_cast<size_t>(e)]));
  return best;
}

double PolygonIndex::distance(const Vec2& p, int extra_rings) const {
  // Rings of cells around p's (clamped) cell, from the first that holds an edge, until the
  // nearest edge found is nearer than any cell outside the rings can be.
  const int ci = column(p.x()), cj = row(p.y());
  double best = std::numeric_limits<double>::infinity();
  const int first =
      empty_rings_[static_cast<size_t>(cj) * static_cast<size_t>(n_) + static_cast<size_t>(ci)];
  for (int r = first;; ++r) {
    for (int j = cj - r; j <= cj + r; ++j)
      for (int i = ci - r; i <= ci + r; ++i) {
        if (std::max(std::abs(i - ci), std::abs(j - cj)) != r) continue;  // the ring only
        if (i >= 0 && j >= 0 && i < n_ && j < n_) best = std::min(best, cell_distance2(p, i, j));
      }
    if (ci - r <= 0 && cj - r <= 0 && ci + r >= n_ - 1 && cj + r >= n_ - 1) break;  // all seen
    if (r - first >= extra_rings && std::isfinite(best)) break;
    const Vec2 lo = box_.min + Vec2(double(ci - r), double(cj - r)).cwiseProduct(cell_);
    const Vec2 hi = box_.min + Vec2(double(ci + r + 1), double(cj + r + 1)).cwiseProduct(cell_);
    const double inset =
        std::max(0.0, std::min({p.x() - lo.x(), hi.x() - p.x(), p.y() - lo.y(), hi.y() - p.y()}));
    if (best <= inset * inset) break;
  }
  return std::sqrt(best);
}

}  // namespace membra
