#include "membra/measure/fitted_curvature.hpp"

#include <algorithm>

#include <Eigen/Dense>

namespace membra {
namespace {

// Each vertex's neighbours along the triangles' edges, sorted, without repeats.
std::vector<std::vector<int>> one_rings(int n, const std::vector<Triangle>& tris) {
  std::vector<std::vector<int>> ring(static_cast<size_t>(n));
  for (const Triangle& t : tris)
    for (int k = 0; k < 3; ++k) {
      ring[static_cast<size_t>(t[k])].push_back(t[(k + 1) % 3]);
      ring[static_cast<size_t>(t[k])].push_back(t[(k + 2) % 3]);
    }
  for (auto& r : ring) {
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end()), r.end());
  }
  return ring;
}

// The vertex's two rings of neighbours (itself left out).
std::vector<int> two_ring(int v, const std::vector<std::vector<int>>& ring) {
  std::vector<int> out;
  for (int a : ring[static_cast<size_t>(v)]) {
    out.push_back(a);
    for (int b : ring[static_cast<size_t>(a)])
      if (b != v) out.push_back(b);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// The fitted graph's K at vertex v with unit normal `normal` over `near`; 0 if it cannot be fitted.
double fitted_at(const Points& x, int v, const Vec3& normal, const std::vector<int>& near) {
  if (near.size() < 5) return 0.0;
  const Vec3& w = normal;
  Eigen::Index axis = 0;
  w.cwiseAbs().minCoeff(&axis);
  const Vec3 u = w.cross(Vec3::Unit(axis)).normalized(), t = w.cross(u);
  Eigen::MatrixXd a(static_cast<Eigen::Index>(near.size()), 5);
  Eigen::VectorXd z(a.rows());
  double scale = 0.0;  // the neighbourhood's size, to condition the columns
  for (int q : near) scale = std::max(scale, (x.col(q) - x.col(v)).norm());
  for (size_t k = 0; k < near.size(); ++k) {
    const Vec3 d = (x.col(near[k]) - x.col(v)) / scale;
    const double px = d.dot(u), py = d.dot(t);
    a.row(static_cast<Eigen::Index>(k)) << px * px, px * py, py * py, px, py;
    z[static_cast<Eigen::Index>(k)] = d.dot(w);
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  if (qr.rank() < 5) return 0.0;
  const Eigen::VectorXd c = qr.solve(z);
  const double slope2 = c[3] * c[3] + c[4] * c[4];
  return (4.0 * c[0] * c[2] - c[1] * c[1]) / ((1.0 + slope2) * (1.0 + slope2) * scale * scale);
}

}  // namespace

std::vector<double> fitted_gaussian_curvature(const Points& x, const std::vector<Triangle>& tris,
                                              const std::vector<bool>& interior) {
  const int n = static_cast<int>(x.cols());
  const auto ring = one_rings(n, tris);
  const Points normal = vertex_normals(x, tris);
  std::vector<double> k(static_cast<size_t>(n), 0.0);
  for (int v = 0; v < n; ++v)
    if (interior[static_cast<size_t>(v)])
      k[static_cast<size_t>(v)] = fitted_at(x, v, normal.col(v), two_ring(v, ring));
  return k;
}

void smooth_density_on_mesh(const Points& x, const std::vector<Triangle>& tris,
                            GaussianCurvature& k) {
  set_smoothed_density(k, fitted_gaussian_curvature(x, tris, k.interior));
}

}  // namespace membra
