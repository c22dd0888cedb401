#include "membra/model/benchmark_problem.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace membra {

BenchmarkProblem make_benchmark_problem(int n) {
  if (n < 3) throw std::invalid_argument("P(n) needs n >= 3");
  BenchmarkProblem b;
  b.n = n;
  Model& m = b.model;
  const GridSheet grid(GridSpec{static_cast<double>(n - 1), static_cast<double>(n - 1), n, n});
  const double pi = std::numbers::pi;
  const int np = n * n;
  m.mass.assign(np, 1.0);
  m.inv_mass.assign(np, 1.0);
  m.reference = Points::Zero(3, np);
  Points x(3, np);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.reference.col(j * n + i) = Vec3(i, j, 0.0);
      x.col(j * n + i) = Vec3(i, j, 1e-3 * std::sin(pi * i / n) * std::sin(pi * j / n));
    }
  const double cx = 0.5 * (n - 1), cy = 0.5 * (n - 1), ax = 0.35 * n, ay = 0.2 * n;
  auto connect = [&](int i0, int j0, int i1, int j1, double k, SpringFamily fam) {
    if (i1 < 0 || i1 >= n || j1 < 0 || j1 >= n) return;
    const int a = j0 * n + i0, b2 = j1 * n + i1;
    const double length = (x.col(b2) - x.col(a)).norm();  // initial length
    const double mx = 0.5 * (i0 + i1) - cx, my = 0.5 * (j0 + j1) - cy;
    const bool inside = (mx / ax) * (mx / ax) + (my / ay) * (my / ay) < 1.0;
    m.springs.add(a, b2, inside ? length : length / 1.5, inside ? 50.0 * k : k, 0.0, fam);
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      connect(i, j, i + 1, j, 1.0, SpringFamily::stretch);
      connect(i, j, i, j + 1, 1.0, SpringFamily::stretch);
      connect(i, j, i + 1, j + 1, 0.5, SpringFamily::shear);
      if (i + 1 < n) connect(i + 1, j, i, j + 1, 0.5, SpringFamily::shear);
      connect(i, j, i + 2, j, 0.1, SpringFamily::flex);
      connect(i, j, i, j + 2, 0.1, SpringFamily::flex);
    }
  b.start = State::at_rest(m);
  b.start.x = x;
  b.triangles = triangulate(grid);
  return b;
}

}  // namespace membra
