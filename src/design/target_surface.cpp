#include "membra/design/target_surface.hpp"

#include <cmath>
#include <stdexcept>

#include "membra/core/units.hpp"
#include "membra/model/formula.hpp"

namespace membra {

double mesh_area(const Points& x, const std::vector<Triangle>& triangles) {
  double a = 0.0;
  for (const Triangle& t : triangles)
    a += 0.5 * (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0])).norm();
  return a;
}

namespace {

// A square grid of n x n vertices over [-s/2, s/2]^2 with z from `height`; with `disk`, only the
// triangles inside the inscribed circle (a hair of slack keeps the rim's vertices).
template <class F>
void grid_patch(TargetSurface& t, double s, int n, bool disk, F height) {
  std::vector<int> index(static_cast<size_t>(n) * n, -1);
  std::vector<Vec3> pts;
  const double h = s / (n - 1), r2 = 0.25 * s * s * (1.0 + 1e-9);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = -0.5 * s + i * h, y = -0.5 * s + j * h;
      if (disk && x * x + y * y > r2) continue;
      index[static_cast<size_t>(j) * n + i] = static_cast<int>(pts.size());
      pts.emplace_back(x, y, height(x, y));
    }
  t.x.resize(3, static_cast<Eigen::Index>(pts.size()));
  for (size_t k = 0; k < pts.size(); ++k) t.x.col(static_cast<Eigen::Index>(k)) = pts[k];
  auto at = [&](int i, int j) { return index[static_cast<size_t>(j) * n + i]; };
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if (a >= 0 && b >= 0 && c >= 0) t.triangles.push_back({a, b, c});
      if (a >= 0 && c >= 0 && d >= 0) t.triangles.push_back({a, c, d});
    }
}

// A disk of diameter s as rings around the centre (ring k has 6k vertices, so triangles stay
// near equilateral and the rim is a true circle), with z from `height`.
template <class F>
void disk_patch(TargetSurface& t, double s, int n, F height) {
  const int rings = std::max(2, (n - 1) / 2);
  std::vector<Vec3> pts = {Vec3(0.0, 0.0, height(0.0, 0.0))};
  std::vector<int> first = {0};  // index of each ring's first vertex
  for (int k = 1; k <= rings; ++k) {
    first.push_back(static_cast<int>(pts.size()));
    const double r = 0.5 * s * k / rings;
    for (int i = 0; i < 6 * k; ++i) {
      const double a = 2.0 * std::acos(-1.0) * i / (6 * k);
      pts.emplace_back(r * std::cos(a), r * std::sin(a), height(r * std::cos(a), r * std::sin(a)));
    }
  }
  t.x.resize(3, static_cast<Eigen::Index>(pts.size()));
  for (size_t k = 0; k < pts.size(); ++k) t.x.col(static_cast<Eigen::Index>(k)) = pts[k];
  for (int i = 0; i < 6; ++i) t.triangles.push_back({0, 1 + i, 1 + (i + 1) % 6});
  for (int k = 2; k <= rings; ++k) {
    // Walk the inner ring (6(k-1) vertices) and the outer one (6k) together by angle.
    const int ni = 6 * (k - 1), no = 6 * k;
    int i = 0, o = 0;
    while (i < ni || o < no) {
      const int a = first[k - 1] + i % ni, b = first[k] + o % no;
      // Advance on the ring whose next vertex comes first in angle.
      if (o < no &&
          (i >= ni || static_cast<double>(o + 1) / no <= static_cast<double>(i + 1) / ni)) {
        t.triangles.push_back({a, b, first[k] + (o + 1) % no});
        ++o;
      } else {
        t.triangles.push_back({a, b, first[k - 1] + (i + 1) % ni});
        ++i;
      }
    }
  }
}

}  // namespace

TargetSurface make_target(const TargetSpec& spec) {
  TargetSurface t;
  t.kind = spec.kind;
  const double s = spec.size, h = spec.height;
  const int n = spec.resolution;
  if (n < 5) throw std::invalid_argument("the target needs at least 5 vertices along a side");
  if (spec.kind != "obj" && !(s > 0.0)) throw std::invalid_argument("size must be positive");
  if (spec.kind == "cap") {
    const double a = 0.5 * s;
    if (!(h > 0.0) || h > a)
      throw std::invalid_argument("a cap's height must be positive and at most its radius");
    const double radius = (a * a + h * h) / (2.0 * h);
    t.disk = true;
    disk_patch(t, s, n, [&](double x, double y) {
      return std::sqrt(std::max(0.0, radius * radius - x * x - y * y)) - (radius - h);
    });
  } else if (spec.kind == "saddle") {
    if (!(h > 0.0)) throw std::invalid_argument("a saddle's height must be positive");
    // z = h (x^2 - y^2) / (s/2)^2: rising h along x, falling h along y.
    grid_patch(t, s, n, false,
               [&](double x, double y) { return h * (x * x - y * y) / (0.25 * s * s); });
  } else if (spec.kind == "cylinder") {
    const double a = 0.5 * s;
    if (!(h > 0.0) || h > a)
      throw std::invalid_argument("a cylinder's height must be positive and at most half its side");
    const double radius = (a * a + h * h) / (2.0 * h);  // chord s, rise h; axis along y
    grid_patch(t, s, n, false, [&](double x, double) {
      return std::sqrt(std::max(0.0, radius * radius - x * x)) - (radius - h);
    });
  } else if (spec.kind == "height_field") {
    FormulaContext ctx;
    ctx.size = Vec2(s, s);
    ctx.center = Vec2::Zero();
    const Formula f(spec.formula, ctx);  // throws std::invalid_argument with muparser's message
    grid_patch(t, s, n, false, [&](double x, double y) { return f(Vec2(x, y)) * units::mm; });
    for (Eigen::Index p = 0; p < t.x.cols(); ++p)
      if (!std::isfinite(t.x(2, p)))
        throw std::invalid_argument("the height formula is not finite everywhere on the patch");
  } else if (spec.kind == "obj") {
    if (spec.obj_triangles.empty())
      throw std::invalid_argument(spec.obj_file + ": the OBJ mesh has no face");
    t.x = spec.obj_x;
    t.triangles = spec.obj_triangles;
  } else {
    throw std::invalid_argument("unknown target kind '" + spec.kind +
                                "' (cap, saddle, cylinder, height_field, obj)");
  }
  // Centre the footprint, lowest point at z = 0.
  const Vec3 lo = t.x.rowwise().minCoeff(), hi = t.x.rowwise().maxCoeff();
  t.x.colwise() -= Vec3(0.5 * (lo.x() + hi.x()), 0.5 * (lo.y() + hi.y()), lo.z());
  // The error's unit: the cap's diameter, the square's side (not its diagonal, which would make
  // the same error look 30 % smaller), the OBJ's larger footprint extent.
  t.diameter = spec.kind == "obj" ? std::max(hi.x() - lo.x(), hi.y() - lo.y()) : s;
  t.area = mesh_area(t.x, t.triangles);
  t.locator = std::make_shared<const TriangleLocator>(t.x.topRows<2>(), t.triangles);
  return t;
}

}  // namespace membra
