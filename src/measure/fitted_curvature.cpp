#include "membra/measure/fitted_curvature.hpp"

#include <algorithm>
#include <utility>

#include <Eigen/Dense>

namespace membra {
namespace {

// Each vertex's neighbours along the triangles' edges, sorted, without repeats: vertex v's are
// near[start[v]] to near[start[v + 1]] (one array: the viewer rebuilds them every frame).
struct OneRings {
  std::vector<int> start, near;
};

OneRings one_rings(int n, const std::vector<Triangle>& tris) {
  OneRings r;
  r.start.assign(static_cast<size_t>(n) + 1, 0);
  for (const Triangle& t : tris)
    for (int k = 0; k < 3; ++k) r.start[static_cast<size_t>(t[k]) + 1] += 2;
  for (size_t v = 0; v < static_cast<size_t>(n); ++v) r.start[v + 1] += r.start[v];
  r.near.resize(static_cast<size_t>(r.start.back()));
  std::vector<int> fill(r.start.begin(), r.start.end() - 1);
  for (const Triangle& t : tris)
    for (int k = 0; k < 3; ++k) {
      int& at = fill[static_cast<size_t>(t[k])];
      r.near[static_cast<size_t>(at++)] = t[(k + 1) % 3];
      r.near[static_cast<size_t>(at++)] = t[(k + 2) % 3];
    }
  // Sorted and unique within each vertex's run, the runs packed again from the front.
  int out = 0;
  for (size_t v = 0; v < static_cast<size_t>(n); ++v) {
    const auto first = r.near.begin() + r.start[v], last = r.near.begin() + r.start[v + 1];
    std::sort(first, last);
    const auto end = std::unique(first, last);
    r.start[v] = out;
    // Moved left within the array, element by element (std::copy may not start inside its source).
    for (auto i = first; i != end; ++i) r.near[static_cast<size_t>(out++)] = *i;
  }
  r.start[static_cast<size_t>(n)] = out;
  r.near.resize(static_cast<size_t>(out));
  return r;
}

// The vertex's two rings of neighbours (itself left out), into `out` (a buffer kept between
// vertices).
void two_ring(int v, const OneRings& ring, std::vector<int>& out) {
  out.clear();
  const auto of = [&](int a) {
    return std::pair{ring.near.begin() + ring.start[static_cast<size_t>(a)],
                     ring.near.begin() + ring.start[static_cast<size_t>(a) + 1]};
  };
  for (auto [i, end] = of(v); i != end; ++i) {
    out.push_back(*i);
    for (auto [j, end2] = of(*i); j != end2; ++j)
      if (*j != v) out.push_back(*j);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

// The fitted graph's K at vertex v with unit normal `normal` over `near`; 0 if it cannot be fitted.
// Rows is the least-squares matrix's type: one on the stack for the usual two rings, a heap one
// for a crowded vertex (the same algorithm on the same numbers either way).
template <typename Rows>
double fitted_at(const Points& x, int v, const Vec3& normal, const std::vector<int>& near) {
  if (near.size() < 5) return 0.0;
  const Vec3& w = normal;
  Eigen::Index axis = 0;
  w.cwiseAbs().minCoeff(&axis);
  const Vec3 u = w.cross(Vec3::Unit(axis)).normalized(), t = w.cross(u);
  Rows a(static_cast<Eigen::Index>(near.size()), 5);
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, Rows::MaxRowsAtCompileTime, 1> z(a.rows());
  double scale = 0.0;  // the neighbourhood's size, to condition the columns
  for (int q : near) scale = std::max(scale, (x.col(q) - x.col(v)).norm());
  for (size_t k = 0; k < near.size(); ++k) {
    const Vec3 d = (x.col(near[k]) - x.col(v)) / scale;
    const double px = d.dot(u), py = d.dot(t);
    a.row(static_cast<Eigen::Index>(k)) << px * px, px * py, py * py, px, py;
    z[static_cast<Eigen::Index>(k)] = d.dot(w);
  }
  const Eigen::ColPivHouseholderQR<Rows> qr(a);
  if (qr.rank() < 5) return 0.0;
  const Eigen::Matrix<double, 5, 1> c = qr.solve(z);
  const double slope2 = c[3] * c[3] + c[4] * c[4];
  return (4.0 * c[0] * c[2] - c[1] * c[1]) / ((1.0 + slope2) * (1.0 + slope2) * scale * scale);
}

constexpr Eigen::Index kStackRows = 64;  // two rings hold 12-40 vertices on the meshes we make
using StackRows = Eigen::Matrix<double, Eigen::Dynamic, 5, 0, kStackRows, 5>;
using HeapRows = Eigen::Matrix<double, Eigen::Dynamic, 5>;

}  // namespace

std::vector<double> fitted_gaussian_curvature(const Points& x, const std::vector<Triangle>& tris,
                                              const std::vector<bool>& interior) {
  const int n = static_cast<int>(x.cols());
  const auto ring = one_rings(n, tris);
  const Points normal = vertex_normals(x, tris);
  std::vector<double> k(static_cast<size_t>(n), 0.0);
  // Each vertex's fit is its own: the threads change no value.
#pragma omp parallel if (n >= 4096)
  {
    std::vector<int> near;
#pragma omp for schedule(static)
    for (int v = 0; v < n; ++v) {
      if (!interior[static_cast<size_t>(v)]) continue;
      two_ring(v, ring, near);
      k[static_cast<size_t>(v)] = static_cast<Eigen::Index>(near.size()) <= kStackRows
                                      ? fitted_at<StackRows>(x, v, normal.col(v), near)
                                      : fitted_at<HeapRows>(x, v, normal.col(v), near);
    }
  }
  return k;
}

void smooth_density_on_mesh(const Points& x, const std::vector<Triangle>& tris,
                            GaussianCurvature& k) {
  set_smoothed_density(k, fitted_gaussian_curvature(x, tris, k.interior));
}

}  // namespace membra
