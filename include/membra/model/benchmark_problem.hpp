#pragma once
// The benchmark problem P(n) (docs/performance.md, "The benchmark problem P(n)"), the yardstick of
// membra's solvers: n x n particles at spacing 1 with unit masses; stretch springs k = 1, both
// diagonals 0.5, skip-one (flex) springs 0.1; every rest length 1/1.5 of the initial length, except
// springs whose midpoint lies inside the ellipse centred on the sheet with semi-axes 0.35 n (x) and
// 0.2 n (y): those keep their length and are 50x stiffer. Particle (i, j) starts at
// (i, j, 1e-3 sin(pi i/n) sin(pi j/n)); nothing is pinned; converged when max |f| < 1e-6.
// Dimensionless: lengths in units of the spacing, forces in units of k x spacing.
#include <vector>

#include "membra/geometry/triangulation.hpp"
#include "membra/model/model.hpp"

namespace membra {

struct BenchmarkProblem {
  int n = 0;
  Model model;
  State start;
  std::vector<Triangle> triangles;  // for the angle-defect total
};

BenchmarkProblem make_benchmark_problem(int n);

}  // namespace membra
