#include "membra/model/pattern_stencil.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <tuple>

#include "membra/model/polygon_index.hpp"

namespace membra {
namespace {

// The pattern's tree, with each primitive's outline as curves and a membership that agrees with
// those curves: a traced primitive answers by its traced polygons, not by its field, so that
// a piece of its outline is tested against the same line it lies on.
struct Node {
  Pattern::Combination kind = Pattern::Combination::primitive;
  const Pattern* pattern = nullptr;
  std::vector<Node> parts;
  std::vector<std::shared_ptr<PolygonIndex>> traced;  // empty for an exact primitive

  bool contains(const Vec2& p) const {
    switch (kind) {
      case Pattern::Combination::union_of:
        return std::any_of(parts.begin(), parts.end(),
                           [&](const Node& n) { return n.contains(p); });
      case Pattern::Combination::difference_of:
        if (!parts[0].contains(p)) return false;
        return std::none_of(parts.begin() + 1, parts.end(),
                            [&](const Node& n) { return n.contains(p); });
      case Pattern::Combination::primitive:
        break;
    }
    if (traced.empty()) return pattern->contains(p);
    bool in = false;  // even-odd over the traced loops
    for (const auto& loop : traced) in ^= loop->contains(p);
    return in;
  }
};

struct Curve {
  PlaneCurve curve;
  int owner;  // the primitive it comes from (-1: the frame)
};

Node build(const Pattern& p, const Box2& frame, const BoundaryOptions& options,
           std::vector<Curve>& curves, int& next_owner) {
  Node node;
  node.kind = p.combination();
  node.pattern = &p;
  if (node.kind != Pattern::Combination::primitive) {
    const auto parts = p.parts();  // kept alive by the pattern that owns them
    for (const PatternPtr& part : parts)
      node.parts.push_back(build(*part, frame, options, curves, next_owner));
    return node;
  }
  const int owner = next_owner++;
  std::vector<PlaneCurve> exact = p.exact_outline();
  if (exact.empty()) {
    // Traced a little beyond its bounds and the frame, so that the frame's edges, not the
    // tracing's clip, bound it.
    const Vec2 margin = Vec2::Constant(4.0 * options.step);
    const Box2 bounds = p.bounds();
    const Box2 box = Box2{bounds.min - margin, bounds.max + margin}.intersect(
        {frame.min - margin, frame.max + margin});
    if (box.empty()) return node;
    for (Polygon2& loop : pattern_boundaries(p, box, options)) {
      for (size_t i = 0; i < loop.size(); ++i)
        exact.push_back(PlaneCurve::segment(loop[i], loop[(i + 1) % loop.size()]));
      node.traced.push_back(std::make_shared<PolygonIndex>(std::move(loop)));
    }
  }
  for (const PlaneCurve& c : exact) curves.push_back({c, owner});
  return node;
}

// Every curve's split parameters: where it meets a curve of another primitive or the frame.
std::vector<std::vector<double>> split_parameters(const std::vector<Curve>& curves) {
  const size_t n = curves.size();
  std::vector<Vec2> lo(n), hi(n);
  for (size_t i = 0; i < n; ++i) curve_bounds(curves[i].curve, lo[i], hi[i]);
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return lo[a].x() < lo[b].x(); });
  std::vector<std::vector<double>> splits(n, std::vector<double>{0.0, 1.0});
  const double pad = 1e-9;
  for (size_t k = 0; k < n; ++k) {
    const size_t i = order[k];
    for (size_t l = k + 1; l < n && lo[order[l]].x() <= hi[i].x() + pad; ++l) {
      const size_t j = order[l];
      if (curves[i].owner == curves[j].owner)
        continue;  // a primitive's outline does not cross itself
      if (lo[j].y() > hi[i].y() + pad || lo[i].y() > hi[j].y() + pad) continue;
      for (const auto& [s, u] : intersections(curves[i].curve, curves[j].curve)) {
        splits[i].push_back(s);
        splits[j].push_back(u);
      }
    }
  }
  return splits;
}

// Quantized point, for matching ends computed from two curves.
using Key = std::pair<long long, long long>;
Key key_of(const Vec2& p, double cell) {
  return {std::llround(p.x() / cell), std::llround(p.y() / cell)};
}

// The pieces between split points across which the resin begins or ends, resin on their left.
std::vector<PlaneCurve> boundary_pieces(const std::vector<Curve>& curves,
                                        std::vector<std::vector<double>> splits, const Node& root,
                                        const Box2& frame) {
  const auto inside = [&](const Vec2& p) {
    return p.x() >= frame.min.x() && p.x() <= frame.max.x() && p.y() >= frame.min.y() &&
           p.y() <= frame.max.y() && root.contains(p);
  };
  const double eps = 1e-8;  // m: the sides of a piece are probed this far off it
  std::vector<PlaneCurve> pieces;
  std::set<std::tuple<Key, Key, Key>> seen;  // collinear overlaps give the same piece twice
  for (size_t i = 0; i < curves.size(); ++i) {
    auto& s = splits[i];
    std::sort(s.begin(), s.end());
    if (curves[i].curve.full_ellipse() && s.size() > 2) {
      // A whole ellipse has no ends: its pieces run from crossing to crossing, the last one
      // across its seam (an arc's parameter may pass 1).
      s.erase(s.begin());
      s.back() = s.front() + 1.0;
    }
    for (size_t k = 0; k + 1 < s.size(); ++k) {
      if (s[k + 1] - s[k] < 1e-12) continue;
      const double mid = 0.5 * (s[k] + s[k + 1]);
      const Vec2 m = curves[i].curve.at(mid), t = curves[i].curve.tangent(mid).normalized();
      const Vec2 n(-t.y(), t.x());
      const bool left = inside(m + eps * n), right = inside(m - eps * n);
      if (left == right) continue;
      PlaneCurve piece =
          left ? curves[i].curve.piece(s[k], s[k + 1]) : curves[i].curve.piece(s[k + 1], s[k]);
      if (!piece.full_ellipse() && (piece.end() - piece.start()).norm() < 1e-12) continue;
      const double cell = 1e-9;
      if (seen.insert({key_of(piece.start(), cell), key_of(piece.at(0.5), cell),
                       key_of(piece.end(), cell)})
              .second)
        pieces.push_back(piece);
    }
  }
  return pieces;
}

// Chains pieces end to start into closed loops.
std::vector<CurveLoop> chain(const std::vector<PlaneCurve>& pieces) {
  const double cell = 1e-6, near = 1e-7;  // m: ends computed from two curves agree far closer
  std::multimap<Key, size_t> by_start;
  for (size_t i = 0; i < pieces.size(); ++i) by_start.emplace(key_of(pieces[i].start(), cell), i);
  std::vector<bool> used(pieces.size(), false);
  const auto next_from = [&](const Vec2& p) -> long {
    const Key k = key_of(p, cell);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        const auto [b, e] = by_start.equal_range({k.first + dx, k.second + dy});
        for (auto it = b; it != e; ++it)
          if (!used[it->second] && (pieces[it->second].start() - p).norm() < near)
            return static_cast<long>(it->second);
      }
    return -1;
  };
  std::vector<CurveLoop> loops;
  for (size_t first = 0; first < pieces.size(); ++first) {
    if (used[first]) continue;
    CurveLoop loop{pieces[first]};
    used[first] = true;
    while ((loop.back().end() - loop.front().start()).norm() >= near) {
      const long next = next_from(loop.back().end());
      if (next < 0) break;  // an open chain (a missed crossing): kept as it is
      used[static_cast<size_t>(next)] = true;
      loop.push_back(pieces[static_cast<size_t>(next)]);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace

std::vector<CurveLoop> stencil_outline(const Pattern& pattern, const Box2& frame,
                                       const BoundaryOptions& options) {
  std::vector<Curve> curves;
  int owner = 0;
  const Node root = build(pattern, frame, options, curves, owner);
  const Vec2 corners[4] = {
      frame.min, {frame.max.x(), frame.min.y()}, frame.max, {frame.min.x(), frame.max.y()}};
  for (int k = 0; k < 4; ++k)
    curves.push_back({PlaneCurve::segment(corners[k], corners[(k + 1) % 4]), -1});
  auto splits = split_parameters(curves);
  return chain(boundary_pieces(curves, std::move(splits), root, frame));
}

double loop_area(const CurveLoop& loop) {
  double twice = 0.0;
  for (const PlaneCurve& c : loop) twice += c.sweep_area2();
  return 0.5 * twice;
}

}  // namespace membra
