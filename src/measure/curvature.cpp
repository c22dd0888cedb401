#include "membra/measure/curvature.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace membra {
namespace {

// The vertices some triangle uses that are not on the boundary (an edge only one triangle has).
std::vector<bool> interior_vertices(int n, const std::vector<Triangle>& tris) {
  std::vector<bool> inside(static_cast<size_t>(n), false);
  for (const Triangle& t : tris)
    for (int k = 0; k < 3; ++k) inside[static_cast<size_t>(t[k])] = true;
  const std::vector<bool> boundary = boundary_vertices(n, tris);
  for (size_t v = 0; v < inside.size(); ++v) inside[v] = inside[v] && !boundary[v];
  return inside;
}

double angle(const Vec3& u, const Vec3& v) {
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

// Mixed Voronoi area of each vertex (Meyer et al. 2003, "Discrete differential-geometry operators
// for triangulated 2-manifolds"): the Voronoi region inside non-obtuse triangles, and half or a
// quarter of an obtuse triangle. On membra's grid (right triangles, valence 4 and 8 alternating)
// it gives every interior vertex one cell, h^2, where a third of the incident area alternates
// between 2/3 and 4/3 h^2.
std::vector<double> mixed_areas(const Points& x, const std::vector<Triangle>& tris) {
  std::vector<double> area(static_cast<size_t>(x.cols()), 0.0);
  for (const Triangle& t : tris) {
    const Vec3 p[3] = {x.col(t[0]), x.col(t[1]), x.col(t[2])};
    const double a = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
    if (a <= 0.0) continue;
    double cot[3];
    int obtuse = -1;
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = p[(k + 1) % 3] - p[k], v = p[(k + 2) % 3] - p[k];
      cot[k] = u.dot(v) / (2.0 * a);
      if (u.dot(v) < 0.0) obtuse = k;
    }
    for (int k = 0; k < 3; ++k) {
      if (obtuse >= 0) {
        area[t[k]] += k == obtuse ? a / 2.0 : a / 4.0;
        continue;
      }
      const int j = (k + 1) % 3, l = (k + 2) % 3;
      area[t[k]] +=
          ((p[j] - p[k]).squaredNorm() * cot[l] + (p[l] - p[k]).squaredNorm() * cot[j]) / 8.0;
    }
  }
  return area;
}

}  // namespace

GaussianCurvature gaussian_curvature(const Points& x, const std::vector<Triangle>& tris) {
  const int n = static_cast<int>(x.cols());
  GaussianCurvature k;
  std::vector<double> angle_sum(static_cast<size_t>(n), 0.0);
  k.area_barycentric.assign(static_cast<size_t>(n), 0.0);
  for (const Triangle& t : tris) {
    const Vec3 a = x.col(t[0]), b = x.col(t[1]), c = x.col(t[2]);
    angle_sum[t[0]] += angle(b - a, c - a);
    angle_sum[t[1]] += angle(c - b, a - b);
    angle_sum[t[2]] += angle(a - c, b - c);
    const double third = (b - a).cross(c - a).norm() / 6.0;
    for (int v = 0; v < 3; ++v) k.area_barycentric[t[v]] += third;
  }
  k.area = mixed_areas(x, tris);
  k.interior = interior_vertices(n, tris);
  k.angle_defect.assign(static_cast<size_t>(n), 0.0);
  k.density.assign(static_cast<size_t>(n), 0.0);
  for (int v = 0; v < n; ++v) {
    if (k.area_barycentric[v] <= 0.0) continue;  // unused vertex
    if (!k.interior[v]) {
      k.angle_defect[v] = std::numbers::pi - angle_sum[v];
      k.boundary += k.angle_defect[v];
      continue;
    }
    const double d = 2.0 * std::numbers::pi - angle_sum[v];
    k.angle_defect[v] = d;
    k.total += d;
    (d > 0.0 ? k.positive : k.negative) += d;
  }
  bool first = true;
  for (int v = 0; v < n; ++v) {
    if (!k.interior[v]) continue;
    k.density[v] = k.angle_defect[v] / k.area[v];
    k.min_density = first ? k.density[v] : std::min(k.min_density, k.density[v]);
    k.max_density = first ? k.density[v] : std::max(k.max_density, k.density[v]);
    first = false;
  }
  return k;
}

void smooth_density_on_grid(const GridSheet& g, GaussianCurvature& k) {
  std::vector<double> out(k.density.size(), 0.0);
  for (int p = 0; p < g.num_particles(); ++p) {
    if (!k.interior[p]) continue;
    const auto [i, j] = g.node(p);
    double defect = 0.0, area = 0.0;
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int q = g.particle(i + di, j + dj);
        if (q < 0 || !k.interior[q]) continue;
        const double w = (2 - std::abs(di)) * (2 - std::abs(dj));  // bilinear: 4, 2, 1
        defect += w * k.angle_defect[q];
        area += w * k.area[q];
      }
    out[p] = defect / area;
  }
  set_smoothed_density(k, std::move(out));
}

void set_smoothed_density(GaussianCurvature& k, std::vector<double> density) {
  k.density = std::move(density);
  // The positive and negative parts follow the smoothed field: raw defects of opposite signs on
  // neighbouring valence-4 and valence-8 vertices would count grid noise as curvature.
  bool first = true;
  k.positive = k.negative = 0.0;
  for (size_t p = 0; p < k.density.size(); ++p) {
    if (!k.interior[p]) continue;
    const double d = k.density[p];
    k.min_density = first ? d : std::min(k.min_density, d);
    k.max_density = first ? d : std::max(k.max_density, d);
    first = false;
    const double part = d * k.area[p];
    (part > 0.0 ? k.positive : k.negative) += part;
  }
}

std::string classify_form(const GaussianCurvature& k, double threshold) {
  const double pos = k.positive, neg = -k.negative;
  if (pos + neg < threshold) return "developable";
  if (pos >= 2.0 * neg) return "synclastic";
  if (neg >= 2.0 * pos) return "anticlastic";
  return "folded";
}

std::vector<double> mean_curvature(const Points& x, const std::vector<Triangle>& tris) {
  const int n = static_cast<int>(x.cols());
  Points lap = Points::Zero(3, n);
  const std::vector<double> area = mixed_areas(x, tris);
  for (const Triangle& t : tris) {
    for (int k = 0; k < 3; ++k) {
      const int i = t[k], j = t[(k + 1) % 3], o = t[(k + 2) % 3];
      // Edge i-j is weighted by half the cotangent of the angle opposite it.
      const Vec3 u = x.col(i) - x.col(o), v = x.col(j) - x.col(o);
      const double cot = u.dot(v) / std::max(u.cross(v).norm(), 1e-300);
      lap.col(i) += 0.5 * cot * (x.col(j) - x.col(i));
      lap.col(j) += 0.5 * cot * (x.col(i) - x.col(j));
    }
  }
  const std::vector<bool> inside = interior_vertices(n, tris);
  std::vector<double> h(static_cast<size_t>(n), 0.0);
  for (int v = 0; v < n; ++v)
    if (inside[v] && area[v] > 0.0) h[v] = lap.col(v).norm() / (2.0 * area[v]);
  return h;
}

}  // namespace membra
