#include "membra/model/polygon_index.hpp"
#include "membra/model/segment_distance.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <stdexcept>

namespace membra {
namespace {

// For every cell of an n x m grid (n along x), the Chebyshev distance (in cells) to the nearest
// cell that holds an edge: a breadth-first search from those cells over the eight neighbours.
std::vector<int> chebyshev_to_nonempty(const std::vector<std::vector<int>>& cells, int n, int m) {
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
        if (u < 0 || w < 0 || u >= n || w >= m || dist[static_cast<size_t>(w * n + u)] >= 0)
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
  // About one edge per cell along the outline; at most 512 cells along the longer side. Square
  // cells, so that a thin polygon's cells are not thinner than the outline's tracing step.
  const Vec2 size = box_.max - box_.min;
  const int cells = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(n))), 1, 512);
  cell_ = std::max(size.maxCoeff() / cells, 1e-12);
  nx_ = std::clamp(static_cast<int>(std::ceil(size.x() / cell_)), 1, cells);
  ny_ = std::clamp(static_cast<int>(std::ceil(size.y() / cell_)), 1, cells);
  rows_.resize(static_cast<size_t>(ny_));
  cells_.resize(static_cast<size_t>(nx_) * static_cast<size_t>(ny_));
  for (int e = 0; e < n; ++e)
    add_edge(e, v_[static_cast<size_t>((e + n - 1) % n)], v_[static_cast<size_t>(e)]);
  empty_rings_ = chebyshev_to_nonempty(cells_, nx_, ny_);
}

void PolygonIndex::add_edge(int e, const Vec2& a, const Vec2& b) {
  const int j0 = row(std::min(a.y(), b.y())), j1 = row(std::max(a.y(), b.y()));
  for (int j = j0; j <= j1; ++j) {
    rows_[static_cast<size_t>(j)].push_back(e);
    // The edge's part inside the band [y_lo, y_hi] of row j (the whole edge if horizontal);
    // the band is closed, so an edge through a cell's corner is listed in both cells.
    const double y_lo = box_.min.y() + j * cell_, y_hi = y_lo + cell_;
    double t0 = 0.0, t1 = 1.0;
    const double dy = b.y() - a.y();
    if (dy != 0.0) {
      const double ta = (y_lo - a.y()) / dy, tb = (y_hi - a.y()) / dy;
      t0 = std::max(0.0, std::min(ta, tb)), t1 = std::min(1.0, std::max(ta, tb));
    }
    const double xa = a.x() + t0 * (b.x() - a.x()), xb = a.x() + t1 * (b.x() - a.x());
    for (int i = column(std::min(xa, xb)); i <= column(std::max(xa, xb)); ++i)
      cells_[static_cast<size_t>(j) * static_cast<size_t>(nx_) + static_cast<size_t>(i)].push_back(
          e);
  }
}

int PolygonIndex::column(double x) const {
  // Clamped as a double first: a query far outside a tiny box must not overflow the int.
  const double c = std::floor((x - box_.min.x()) / cell_);
  return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(nx_ - 1)));
}

int PolygonIndex::row(double y) const {
  const double c = std::floor((y - box_.min.y()) / cell_);
  return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(ny_ - 1)));
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
  for (int e : cells_[static_cast<size_t>(j) * static_cast<size_t>(nx_) + static_cast<size_t>(i)])
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
      empty_rings_[static_cast<size_t>(cj) * static_cast<size_t>(nx_) + static_cast<size_t>(ci)];
  const auto visit = [&](int i, int j) {
    if (i >= 0 && j >= 0 && i < nx_ && j < ny_) best = std::min(best, cell_distance2(p, i, j));
  };
  for (int r = first;; ++r) {
    if (r == 0) {
      visit(ci, cj);
    } else {  // the ring's perimeter only: its top and bottom rows, then its sides
      for (int i = ci - r; i <= ci + r; ++i) visit(i, cj - r), visit(i, cj + r);
      for (int j = cj - r + 1; j <= cj + r - 1; ++j) visit(ci - r, j), visit(ci + r, j);
    }
    if (ci - r <= 0 && cj - r <= 0 && ci + r >= nx_ - 1 && cj + r >= ny_ - 1) break;  // all seen
    if (r - first >= extra_rings && std::isfinite(best)) break;
    const Vec2 lo = box_.min + cell_ * Vec2(double(ci - r), double(cj - r));
    const Vec2 hi = box_.min + cell_ * Vec2(double(ci + r + 1), double(cj + r + 1));
    const double inset =
        std::max(0.0, std::min({p.x() - lo.x(), hi.x() - p.x(), p.y() - lo.y(), hi.y() - p.y()}));
    if (best <= inset * inset) break;
  }
  return std::sqrt(best);
}

}  // namespace membra
