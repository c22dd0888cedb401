#include "membra/measure/mesh_hole_edge.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <set>

#include <Eigen/Dense>

namespace membra {
namespace mesh_hole_edge_detail {
namespace {

// The mesh's boundary as loops of particles, each in order (edges with one triangle).
std::vector<std::vector<int>> boundary_loops(const std::vector<Triangle>& triangles) {
  std::map<std::pair<int, int>, int> count;
  for (const Triangle& t : triangles)
    for (int e = 0; e < 3; ++e) {
      const int a = t[e], b = t[(e + 1) % 3];
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  std::map<int, int> next;  // each boundary edge as its triangle runs it
  for (const Triangle& t : triangles)
    for (int e = 0; e < 3; ++e) {
      const int a = t[e], b = t[(e + 1) % 3];
      if (count[{std::min(a, b), std::max(a, b)}] == 1) next[a] = b;
    }
  std::vector<std::vector<int>> loops;
  std::set<int> seen;
  for (const auto& [start, unused] : next) {
    if (seen.contains(start)) continue;
    std::vector<int> loop;
    for (int p = start; !seen.contains(p) && next.contains(p); p = next[p]) {
      seen.insert(p);
      loop.push_back(p);
    }
    if (loop.size() >= 3) loops.push_back(std::move(loop));
  }
  return loops;
}

// The distance from c along the unit direction d to the polygon, or infinity.
double ray_to_polygon(const Vec2& c, const Vec2& d, const std::vector<Vec2>& poly) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < poly.size(); ++k) {
    const Vec2 &a = poly[k], &b = poly[(k + 1) % poly.size()], e = b - a;
    const double den = d.x() * e.y() - d.y() * e.x();
    if (std::abs(den) < 1e-300) continue;
    const Vec2 w = a - c;
    const double t = (w.x() * e.y() - w.y() * e.x()) / den;
    const double s = (w.x() * d.y() - w.y() * d.x()) / den;
    if (t > 0.0 && s >= 0.0 && s <= 1.0) best = std::min(best, t);
  }
  return best;
}

// The samples: triangles whose centroid lies within kWedge (rad) of the ray and within kBand
// times the edge's distance from the centre.
constexpr double kWedge = 0.25, kBand = 2.5;

double wrapped(double a) {
  return std::remainder(a, 2.0 * std::numbers::pi);
}

}  // namespace
}  // namespace mesh_hole_edge_detail

std::optional<MeshHole> find_mesh_hole(const Sheet& sheet, const std::vector<Vec2>& removed) {
  using namespace mesh_hole_edge_detail;
  if (removed.empty()) return std::nullopt;
  Vec2 mean = Vec2::Zero();
  for (const Vec2& p : removed) mean += p;
  mean /= static_cast<double>(removed.size());
  const std::set<int> rim(sheet.mesh.rim.begin(), sheet.mesh.rim.end());
  const Points& ref = sheet.model.reference;
  std::optional<MeshHole> best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::vector<int>& loop : boundary_loops(sheet.triangles)) {
    if (std::any_of(loop.begin(), loop.end(), [&](int p) { return rim.contains(p); })) continue;
    double area = 0.0, length = 0.0;
    Vec2 centroid = Vec2::Zero();
    for (size_t k = 0; k < loop.size(); ++k) {
      const Vec2 a = ref.col(loop[k]).head<2>(), b = ref.col(loop[(k + 1) % loop.size()]).head<2>();
      const double cross = a.x() * b.y() - a.y() * b.x();
      area += 0.5 * cross;
      centroid += (a + b) * cross / 6.0;
      length += (b - a).norm();
    }
    // A slit's loop encloses nothing: its area is round-off, its centroid anywhere.
    if (!(std::abs(area) > 1e-6 * length * length)) continue;
    centroid /= area;
    const double d = (centroid - mean).norm();
    if (d >= best_distance) continue;
    best_distance = d;
    const double edge = length / static_cast<double>(loop.size());
    best = MeshHole{std::move(loop), centroid, std::sqrt(std::abs(area) / std::numbers::pi), edge};
  }
  return best;
}

std::optional<double> mesh_edge_hoop(const Sheet& sheet, const Points& x, const MeshHole& hole,
                                     double angle) {
  using namespace mesh_hole_edge_detail;
  const MembraneTriangles& tri = sheet.model.membrane_triangles;
  const Points& ref = sheet.model.reference;
  std::vector<Vec2> poly;
  for (int p : hole.boundary) poly.push_back(ref.col(p).head<2>());
  constexpr int kTerms = 7;
  using Row = Eigen::Matrix<double, kTerms, 1>;
  std::vector<Row> rows;
  std::vector<double> values;
  for (int i = 0; i < tri.size(); ++i) {
    const auto& v = tri.v[static_cast<size_t>(i)];
    const Vec2 c = (ref.col(v[0]) + ref.col(v[1]) + ref.col(v[2])).head<2>() / 3.0 - hole.centre;
    const double r = c.norm(), phi = std::atan2(c.y(), c.x()), off = wrapped(phi - angle);
    if (std::abs(off) > kWedge) continue;
    const double edge = ray_to_polygon(hole.centre, c / r, poly);
    if (!(r > edge - 1e-12) || r > kBand * edge) continue;
    // The paper's hoop direction carried to the triangle's current plane: F t.
    Eigen::Matrix<double, 3, 2> now, rest;
    now << x.col(v[1]) - x.col(v[0]), x.col(v[2]) - x.col(v[0]);
    rest << ref.col(v[1]) - ref.col(v[0]), ref.col(v[2]) - ref.col(v[0]);
    const Eigen::Matrix2d rest2 = rest.topRows<2>();
    const Vec3 t = (now * rest2.inverse() * Vec2(-std::sin(phi), std::cos(phi))).normalized();
    const double u = (edge / r) * (edge / r), u2 = u * u, off2 = off * off;
    rows.push_back((Row() << 1.0, u, u2, off, u2 * off, off2, u2 * off2).finished());
    values.push_back(t.dot(tri.stress_tensor(i, x) * t));
  }
  if (rows.size() < 3 * kTerms) return std::nullopt;
  Eigen::MatrixXd a(rows.size(), kTerms);
  Eigen::VectorXd b(rows.size());
  for (size_t k = 0; k < rows.size(); ++k) {
    a.row(static_cast<Eigen::Index>(k)) = rows[k].transpose();
    b[static_cast<Eigen::Index>(k)] = values[k];
  }
  const Eigen::VectorXd c = a.colPivHouseholderQr().solve(b);
  return c[0] + c[1] + c[2];  // u = 1 on the ray
}

HoleEdge mesh_hole_edge(const Sheet& sheet, const Points& x, const std::vector<Vec2>& removed,
                        int rays) {
  HoleEdge out;
  const std::optional<MeshHole> hole = find_mesh_hole(sheet, removed);
  if (!hole) return out;
  out.centre = hole->centre;
  out.radius = hole->radius;
  for (int k = 0; k < rays; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / rays;
    const std::optional<double> v = mesh_edge_hoop(sheet, x, *hole, angle);
    if (!v || (out.valid && *v <= out.value)) continue;
    out.valid = true;
    out.value = *v;
    out.angle = angle;
  }
  return out;
}

}  // namespace membra
