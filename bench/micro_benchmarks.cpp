// Google Benchmark micro-benchmarks of membra's kernels on the benchmark problem P(n) and on a
// latex sheet with bending. Counters: ns per spring (force pass) or per particle. CI runs them
// as a smoke test only (ctest label "bench", a few iterations); docs/performance.md has numbers.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <omp.h>
#include <Eigen/CholmodSupport>

#include "membra/measure/colormap.hpp"
#include "membra/measure/curvature.hpp"
#include "membra/measure/fitted_curvature.hpp"
#include "membra/measure/self_intersection.hpp"
#include "membra/measure/stress_tensor.hpp"
#include "membra/model/benchmark_problem.hpp"
#include "membra/model/continuum_sheet.hpp"
#include "membra/model/forces.hpp"
#include "membra/model/sheet.hpp"
#include "membra/render/renderer.hpp"
#include "membra/solve/hessian_assembler.hpp"
#include "membra/solve/newton_workspace.hpp"

namespace {

using membra::Points;

void set_per_item(benchmark::State& state, double items) {
  state.counters["ns_per_item"] =
      benchmark::Counter(items * static_cast<double>(state.iterations()) * 1e-9,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// One static force pass over P(n): springs only (stretch, shear, flex).
void BM_ForcePassP(benchmark::State& state) {
  const auto p = membra::make_benchmark_problem(static_cast<int>(state.range(0)));
  Points f;
  for (auto _ : state) {
    membra::compute_static_forces(p.model, p.start.x, f);
    benchmark::DoNotOptimize(f.data());
  }
  set_per_item(state, p.model.springs.size());  // ns per spring
}
BENCHMARK(BM_ForcePassP)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMicrosecond);

// The same pass with positions and forces as a structure of arrays (x[], y[], z[]), springs only,
// single-threaded: the layout candidate of the speed issue, measured against membra's
// column-per-particle layout above (docs/performance.md: no gain; a spring's two ends are
// gathered either way, and three coordinates side by side share a cache line).
void BM_ForcePassSoA(benchmark::State& state) {
  const auto p = membra::make_benchmark_problem(static_cast<int>(state.range(0)));
  const membra::Springs& s = p.model.springs;
  const int n = p.model.num_particles();
  std::vector<double> x(p.start.x.row(0).begin(), p.start.x.row(0).end()),
      y(p.start.x.row(1).begin(), p.start.x.row(1).end()),
      z(p.start.x.row(2).begin(), p.start.x.row(2).end());
  std::vector<double> fx(static_cast<size_t>(n)), fy(fx.size()), fz(fx.size());
  for (auto _ : state) {
    std::fill(fx.begin(), fx.end(), 0.0);
    std::fill(fy.begin(), fy.end(), 0.0);
    std::fill(fz.begin(), fz.end(), 0.0);
    for (int i = 0; i < s.size(); ++i) {
      const auto a = static_cast<size_t>(s.a[i]), b = static_cast<size_t>(s.b[i]);
      const double dx = x[b] - x[a], dy = y[b] - y[a], dz = z[b] - z[a];
      const double l = std::sqrt(dx * dx + dy * dy + dz * dz);
      const double c = s.stiffness[i] * (1.0 - s.rest_length[i] / l);
      fx[a] += c * dx, fy[a] += c * dy, fz[a] += c * dz;
      fx[b] -= c * dx, fy[b] -= c * dy, fz[b] -= c * dz;
    }
    benchmark::DoNotOptimize(fx.data());
    benchmark::DoNotOptimize(fy.data());
    benchmark::DoNotOptimize(fz.data());
  }
  set_per_item(state, s.size());  // ns per spring
}
BENCHMARK(BM_ForcePassSoA)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMicrosecond);

// One force pass over a latex sheet with plate bending.
void BM_ForcePassSheet(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto s = membra::build_sheet({0.2, 0.2, n, n}, membra::SheetOptions{});
  Points x = s.model.reference;
  for (int p = 0; p < x.cols(); ++p) x(2, p) = 1e-3 * std::sin(30.0 * x(0, p));
  Points f;
  for (auto _ : state) {
    membra::compute_static_forces(s.model, x, f);
    benchmark::DoNotOptimize(f.data());
  }
  set_per_item(state, s.model.num_particles());  // ns per particle
}
BENCHMARK(BM_ForcePassSheet)->Arg(64)->Arg(256)->Unit(benchmark::kMicrosecond);

void BM_Curvature(benchmark::State& state) {
  const auto p = membra::make_benchmark_problem(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    auto k = membra::gaussian_curvature(p.start.x, p.triangles);
    benchmark::DoNotOptimize(k.angle_defect.data());
  }
  set_per_item(state, p.model.num_particles());  // ns per particle
}
BENCHMARK(BM_Curvature)->Arg(64)->Arg(256)->Unit(benchmark::kMicrosecond);

// A 200 mm latex square on the continuum model, meshed with edges up to `max_edge_mm`, bent
// into the saddle z = 0.3 x^2 - 0.2 y^2 (m) so that every element is nontrivial.
struct BentMesh {
  explicit BentMesh(long max_edge_mm)
      : sheet(membra::build_continuum_sheet([&] {
          membra::ContinuumSpec spec;
          spec.mesh.max_edge = 1e-3 * static_cast<double>(max_edge_mm);
          return spec;
        }())),
        x(sheet.model.reference) {
    for (Eigen::Index p = 0; p < x.cols(); ++p)
      x(2, p) = 0.3 * x(0, p) * x(0, p) - 0.2 * x(1, p) * x(1, p);
  }
  membra::Sheet sheet;
  Points x;
};

// The curvature the viewer colours a continuum sheet by, every frame: the angle defect smoothed
// by a quadric fitted over each vertex's two rings (fitted_curvature.hpp), on a 200 mm latex
// square meshed with edges up to arg mm (10: about 1 100 vertices; 3: about 11 000, the size of
// the ellipse's and exp2's default meshes), bent into a saddle.
void BM_FittedCurvature(benchmark::State& state) {
  const BentMesh b(state.range(0));
  const membra::Sheet& sheet = b.sheet;
  const Points& x = b.x;
  for (auto _ : state) {
    membra::GaussianCurvature k = membra::gaussian_curvature(x, sheet.triangles);
    membra::smooth_density_on_mesh(x, sheet.triangles, k);
    benchmark::DoNotOptimize(k.density.data());
  }
  set_per_item(state, sheet.model.num_particles());  // ns per particle
}
BENCHMARK(BM_FittedCurvature)->Arg(10)->Arg(3)->Unit(benchmark::kMillisecond);

// The check every run ends with, for a form that passes through itself (self_intersection.hpp),
// on the same meshes and saddle.
void BM_SelfIntersection(benchmark::State& state) {
  const BentMesh b(state.range(0));
  const membra::Sheet& sheet = b.sheet;
  const Points& x = b.x;
  for (auto _ : state) {
    const membra::SelfIntersection si = membra::self_intersections(x, sheet.triangles);
    benchmark::DoNotOptimize(si.pairs);
  }
  set_per_item(state, static_cast<double>(sheet.triangles.size()));  // ns per triangle
}
BENCHMARK(BM_SelfIntersection)->Arg(10)->Arg(3)->Unit(benchmark::kMillisecond);

// What self-contact (self_contact.hpp) adds to every Newton iteration on a sheet that does not
// touch itself: the check for pairs nearer than 1.5 gaps, and the step limit of a step moving
// each particle up to 2 mm, on the same meshes and saddle.
void BM_SelfContactRefresh(benchmark::State& state) {
  const BentMesh b(state.range(0));
  membra::SelfContact c;
  c.cover(b.sheet.triangles, b.sheet.model.reference, 1e-3, 1e3, 3e-3);
  for (auto _ : state) benchmark::DoNotOptimize(c.refresh(b.x));
  set_per_item(state, b.sheet.model.num_particles());  // ns per particle
}
BENCHMARK(BM_SelfContactRefresh)->Arg(10)->Arg(3)->Unit(benchmark::kMillisecond);

void BM_SelfContactStepLimit(benchmark::State& state) {
  const BentMesh b(state.range(0));
  membra::SelfContact c;
  c.cover(b.sheet.triangles, b.sheet.model.reference, 1e-3, 1e3, 3e-3);
  c.refresh(b.x);
  const Points step = 1e-3 * Points::Random(3, b.x.cols());
  for (auto _ : state) benchmark::DoNotOptimize(c.step_limit(b.x, step, Points()));
  set_per_item(state, b.sheet.model.num_particles());  // ns per particle
}
BENCHMARK(BM_SelfContactStepLimit)->Arg(10)->Arg(3)->Unit(benchmark::kMillisecond);

// A latex sheet with bending, n x n, bent out of plane into a saddle so that every element's
// Hessian is nontrivial, with every coordinate free (dof k is coordinate k).
struct BentSheet {
  explicit BentSheet(int n)
      : sheet(membra::build_sheet({0.2, 0.2, n, n}, membra::SheetOptions{})),
        x(sheet.model.reference),
        dof(static_cast<size_t>(x.size())) {
    for (Eigen::Index p = 0; p < x.cols(); ++p)
      x(2, p) = 0.3 * x(0, p) * x(0, p) - 0.2 * x(1, p) * x(1, p);
    for (size_t k = 0; k < dof.size(); ++k) dof[k] = static_cast<int>(k);
  }
  membra::Sheet sheet;
  membra::Points x;
  std::vector<int> dof;
};

// One assembly of the analytic Hessian into the fixed pattern (the pattern built once, outside
// the loop, as Newton does), exact (arg 1 = 0) or element-wise projected (1), on a latex sheet
// with bending, bent out of plane so that every element's Hessian is nontrivial.
void BM_HessianAssembly(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const bool project = state.range(1) != 0;
  const BentSheet b(n);
  membra::HessianAssembler a(b.sheet.model, b.dof, static_cast<int>(b.dof.size()));
  for (auto _ : state) {
    const auto& h = a.assemble(b.x, project);
    benchmark::DoNotOptimize(h.valuePtr());
  }
  set_per_item(state, b.sheet.model.num_particles());  // ns per particle
}
BENCHMARK(BM_HessianAssembly)->Args({64, 0})->Args({64, 1})->Unit(benchmark::kMillisecond);

// The same on the continuum model: a 200 mm latex square meshed with edges up to arg 0 mm
// (10: exp5_shrink's default mesh size, about 1 100 vertices), membrane and shell triangles,
// bent into the same saddle; exact (arg 1 = 0) or projected (1). Each shell triangle's block
// couples the 12 particles of its stencil (docs/model.md, "Bending").
void BM_ContinuumHessianAssembly(benchmark::State& state) {
  const BentMesh b(state.range(0));
  const membra::Sheet& sheet = b.sheet;
  const Points& x = b.x;
  std::vector<int> dof(static_cast<size_t>(x.size()));
  for (size_t k = 0; k < dof.size(); ++k) dof[k] = static_cast<int>(k);
  membra::HessianAssembler a(sheet.model, dof, static_cast<int>(dof.size()));
  for (auto _ : state) {
    const auto& h = a.assemble(x, state.range(1) != 0);
    benchmark::DoNotOptimize(h.valuePtr());
  }
  set_per_item(state, sheet.model.num_particles());  // ns per particle
}
BENCHMARK(BM_ContinuumHessianAssembly)->Args({10, 0})->Args({10, 1})->Unit(benchmark::kMillisecond);

// One numeric factorization of that Hessian (made positive definite by a shift of its
// diagonal) by CHOLMOD's supernodal Cholesky, as Newton factorizes every iteration, with the
// fill-reducing ordering chosen by CHOLMOD's default strategy (arg 1 = 0), AMD alone (1), METIS
// (2) or CHOLMOD's nested dissection (3); the symbolic analysis is done once, outside the loop.
void BM_Factorization(benchmark::State& state) {
  const BentSheet b(static_cast<int>(state.range(0)));
  membra::HessianAssembler a(b.sheet.model, b.dof, static_cast<int>(b.dof.size()));
  a.assemble(b.x, true);
  const Eigen::VectorXd diag = a.diagonal().cwiseAbs();
  const Eigen::SparseMatrix<double>& h = a.add_to_diagonal(1e-6 * diag);
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>> llt;
  llt.cholmod().print = 0;
  const int orderings[] = {-1, CHOLMOD_AMD, CHOLMOD_METIS, CHOLMOD_NESDIS};
  if (const int o = orderings[state.range(1)]; o >= 0) {
    llt.cholmod().nmethods = 1;
    llt.cholmod().method[0].ordering = o;
  }
  llt.analyzePattern(h);
  // As Newton factorizes: CHOLMOD's fixed 4 threads stay off (restored for the kernels after).
  const int levels = omp_get_max_active_levels();
  omp_set_max_active_levels(0);
  for (auto _ : state) {
    llt.factorize(h);
    if (llt.info() != Eigen::Success) state.SkipWithError("not positive definite");
  }
  omp_set_max_active_levels(levels);
  state.counters["nnz_L_per_particle"] =
      static_cast<double>(llt.cholmod().lnz) / static_cast<double>(b.sheet.model.num_particles());
  set_per_item(state, b.sheet.model.num_particles());  // ns per particle
}
BENCHMARK(BM_Factorization)->ArgsProduct({{64, 128}, {0, 1, 2, 3}})->Unit(benchmark::kMillisecond);

// What a Newton solve sets up before its first factorization (NewtonWorkspace): the Hessians'
// pattern alone (arg 1 = 0), or with CHOLMOD's symbolic analysis (1: the ordering and the
// supernodes). Against BM_Factorization it says what a path saves by keeping it from one
// increment to the next (docs/solver.md).
void BM_NewtonSetup(benchmark::State& state) {
  const BentSheet b(static_cast<int>(state.range(0)));
  const int ndof = static_cast<int>(b.dof.size());
  for (auto _ : state) {
    membra::NewtonWorkspace ws(b.sheet.model, b.dof, ndof);
    if (state.range(1) != 0) ws.llt.analyzePattern(ws.exact.lower());
    benchmark::DoNotOptimize(ws.exact.lower().valuePtr());
  }
  set_per_item(state, b.sheet.model.num_particles());  // ns per particle
}
BENCHMARK(BM_NewtonSetup)->ArgsProduct({{32, 64, 128}, {0, 1}})->Unit(benchmark::kMillisecond);

void BM_StressTensor(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto s = membra::build_sheet({0.2, 0.2, n, n}, membra::SheetOptions{});
  for (auto _ : state) {
    auto t = membra::node_stress(s.grid, s.model, s.model.reference, 5e-4);
    benchmark::DoNotOptimize(t.sigma.data());
  }
  set_per_item(state, s.model.num_particles());  // ns per particle
}
BENCHMARK(BM_StressTensor)->Arg(64)->Unit(benchmark::kMicrosecond);

// One picture of a run (curvature.png's default 1200 x 900) of a 64 x 64 sheet bowed into a
// dome, with and without its soft shadow (Arg 1/0): what each of a run's pictures costs.
void BM_RenderPicture(benchmark::State& state) {
  const auto s = membra::build_sheet({0.2, 0.2, 64, 64}, membra::SheetOptions{});
  Points x = s.model.reference;
  std::vector<membra::Rgb> colors;
  for (int p = 0; p < x.cols(); ++p) {
    const double u = x(0, p) - 0.1, v = x(1, p) - 0.1;
    x(2, p) = -2.0 * (u * u + v * v);
    colors.push_back(membra::colormap(u, -0.1, 0.1, membra::ColourMap::paper));
  }
  membra::Renderer renderer(1200, 900);
  const membra::Camera camera{-60.0, 35.0, 1.1, state.range(0) == 1};
  for (auto _ : state) {
    const membra::Image img = renderer.render(x, s.triangles, colors, camera, nullptr, "Dome");
    benchmark::DoNotOptimize(img.rgb.data());
  }
}
BENCHMARK(BM_RenderPicture)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
