// Google Benchmark micro-benchmarks of membra's kernels on the benchmark problem P(n) and on a
// latex sheet with bending. Counters: ns per spring (force pass) or per particle. CI runs them
// as a smoke test only (ctest label "bench", a few iterations); docs/performance.md has numbers.
#include <benchmark/benchmark.h>

#include "membra/measure/curvature.hpp"
#include "membra/measure/stress_tensor.hpp"
#include "membra/model/benchmark_problem.hpp"
#include "membra/model/forces.hpp"
#include "membra/model/sheet.hpp"
#include "membra/solve/newton_solver.hpp"

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

void BM_HessianAssembly(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto s = membra::build_sheet({0.2, 0.2, n, n}, membra::SheetOptions{});
  for (auto _ : state) {
    auto h = membra::potential_hessian(s.model, s.model.reference);
    benchmark::DoNotOptimize(h.valuePtr());
  }
  set_per_item(state, s.model.num_particles());  // ns per particle
}
BENCHMARK(BM_HessianAssembly)->Arg(64)->Unit(benchmark::kMillisecond);

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

}  // namespace

BENCHMARK_MAIN();
