#include "membra/model/top_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

namespace membra {
namespace {

Eigen::Matrix2Xd plane_of(const Membrane& m) {
  if (!m.sheet.continuum() || m.sheet.triangles.empty())
    throw std::invalid_argument("top view: a continuum sheet with triangles");
  return m.state.x.topRows<2>();
}

// Samples along a to b at most `spacing` apart, a included, b not.
void sample_segment(const Vec2& a, const Vec2& b, double spacing, std::vector<Vec2>& out) {
  const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / spacing)));
  for (int k = 0; k < n; ++k) out.push_back(a + (static_cast<double>(k) / n) * (b - a));
}

}  // namespace

std::string TopView::extent() const {
  char buf[120];
  std::snprintf(buf, sizeof buf,
                " (seen from above, the sheet now lies within x %.1f to %.1f mm, "
                "y %.1f to %.1f mm)",
                1e3 * lo_.x(), 1e3 * hi_.x(), 1e3 * lo_.y(), 1e3 * hi_.y());
  return buf;
}

namespace {

// Refuses a jump between two pulled-back points far longer than between the points drawn: the
// drawn line passed from one layer of a sheet folded over itself to another (or over a flank
// seen almost edge-on), and a straight boundary between the two paper points would cut through
// sheet the line never crossed.
void check_one_layer(const TopView& view, const Vec2& drawn_a, const Vec2& drawn_b,
                     const Vec2& paper_a, const Vec2& paper_b) {
  if ((paper_b - paper_a).norm() <= 10.0 * (drawn_b - drawn_a).norm() + 1e-9) return;
  char at[80];
  std::snprintf(at, sizeof at, "%.1f, %.1f mm", 1e3 * drawn_b.x(), 1e3 * drawn_b.y());
  throw std::invalid_argument(std::string("the cut passes from one layer of the sheet to another "
                                          "as seen from above, at ") +
                              at + view.extent() + "; draw it where one layer lies");
}

// The last point on the sheet between `on` (on it) and `off` (off it), by bisection.
Vec2 edge_between(const TopView& view, Vec2 on, Vec2 off) {
  for (int k = 0; k < 50; ++k) {
    const Vec2 mid = 0.5 * (on + off);
    (view.paper_at(mid) ? on : off) = mid;
  }
  return on;
}

// The polyline without the points closer than `gap` to the last one kept (a sample a hair from
// where the line crosses the sheet's edge would leave the mesher a sliver there); its ends stay.
std::vector<Vec2> thinned(const std::vector<Vec2>& line, double gap) {
  std::vector<Vec2> out{line.front()};
  for (size_t k = 1; k + 1 < line.size(); ++k)
    if ((line[k] - out.back()).norm() >= gap && (line[k] - line.back()).norm() >= gap)
      out.push_back(line[k]);
  out.push_back(line.back());
  return out;
}

}  // namespace

TopView::TopView(const Membrane& m) : m_(m), locator_(plane_of(m), m.sheet.triangles) {
  const Eigen::Matrix2Xd xy = m.state.x.topRows<2>();
  lo_ = xy.rowwise().minCoeff();
  hi_ = xy.rowwise().maxCoeff();
}

std::optional<Vec2> TopView::paper_at(const Vec2& q) const {
  const Points& x = m_.state.x;
  const Points& ref = m_.sheet.model.reference;
  double top = -std::numeric_limits<double>::infinity();
  std::optional<Vec2> out;
  for (const int t : locator_.candidates(q)) {
    const Triangle& tri = m_.sheet.triangles[static_cast<size_t>(t)];
    const Vec2 a = x.col(tri[0]).head<2>(), b = x.col(tri[1]).head<2>(),
               c = x.col(tri[2]).head<2>();
    Eigen::Matrix2d e;
    e << b - a, c - a;
    const double det = e.determinant();
    if (!(std::abs(det) > 1e-30)) continue;  // seen edge-on: the neighbours hold q
    const Vec2 w = e.inverse() * (q - a);    // weights of b and c
    const double wa = 1.0 - w.x() - w.y();
    constexpr double eps = -1e-9;
    if (wa < eps || w.x() < eps || w.y() < eps) continue;
    const double z = wa * x(2, tri[0]) + w.x() * x(2, tri[1]) + w.y() * x(2, tri[2]);
    if (z <= top) continue;
    top = z;
    out = (wa * ref.col(tri[0]) + w.x() * ref.col(tri[1]) + w.y() * ref.col(tri[2])).head<2>();
  }
  return out;
}

std::vector<Vec2> pull_back_line(const TopView& view, const std::vector<Vec2>& line,
                                 double spacing) {
  if (line.size() < 2) throw std::invalid_argument("a cut needs at least two points");
  std::vector<Vec2> samples;
  for (size_t k = 0; k + 1 < line.size(); ++k)
    sample_segment(line[k], line[k + 1], spacing, samples);
  samples.push_back(line.back());
  std::vector<Vec2> out, drawn;  // paper points and where each was drawn
  const auto add = [&](const Vec2& q, const Vec2& p) {
    if (!out.empty()) check_one_layer(view, drawn.back(), q, out.back(), p);
    out.push_back(p), drawn.push_back(q);
  };
  const auto add_edge = [&](const Vec2& on, const Vec2& off) {
    const Vec2 q = edge_between(view, on, off);
    add(q, *view.paper_at(q));
  };
  bool left = false;  // the line has been on the sheet and run off it
  for (size_t k = 0; k < samples.size(); ++k) {
    const std::optional<Vec2> p = view.paper_at(samples[k]);
    if (!p) {
      if (!out.empty() && !left) add_edge(samples[k - 1], samples[k]), left = true;
      continue;
    }
    if (left)
      throw std::invalid_argument(
          "the cut leaves the sheet as it lies now (seen from above) and comes back onto it; "
          "draw one cut per piece" +
          view.extent());
    if (out.empty() && k > 0) add_edge(samples[k], samples[k - 1]);
    add(samples[k], *p);
  }
  if (out.size() < 2)
    throw std::invalid_argument("the cut does not cross the sheet as it lies now" + view.extent());
  return thinned(out, 0.25 * spacing);
}

std::vector<Vec2> pull_back_polygon(const TopView& view, const std::vector<Vec2>& polygon,
                                    double spacing) {
  std::vector<Vec2> samples;
  for (size_t k = 0; k < polygon.size(); ++k)
    sample_segment(polygon[k], polygon[(k + 1) % polygon.size()], spacing, samples);
  std::vector<Vec2> out;
  for (const Vec2& q : samples) {
    const std::optional<Vec2> p = view.paper_at(q);
    if (!p) {
      char at[80];
      std::snprintf(at, sizeof at, "%.1f, %.1f mm", 1e3 * q.x(), 1e3 * q.y());
      throw std::invalid_argument(
          std::string("the hole reaches past the sheet as it lies now at ") + at + view.extent() +
          "; on the continuum model a hole lies inside the sheet");
    }
    if (!out.empty()) check_one_layer(view, samples[out.size() - 1], q, out.back(), *p);
    out.push_back(*p);
  }
  if (out.size() > 1) check_one_layer(view, samples.back(), samples.front(), out.back(), out[0]);
  return out;
}

}  // namespace membra
