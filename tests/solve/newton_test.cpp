// The Newton solver: its Hessian, its gauge in every orientation, quadratic convergence near a
// minimum, the escape from a saddle, and the continuation variant (ptc).
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include <gtest/gtest.h>

#include "membra/model/bilayer.hpp"
#include "membra/model/forces.hpp"
#include "membra/model/membrane.hpp"
#include "membra/model/sheet.hpp"
#include "membra/solve/hessian_assembler.hpp"
#include "membra/solve/newton_solver.hpp"
#include "membra/solve/stability.hpp"
#include "membra/solve/static_solver.hpp"
#include "test_util.hpp"

namespace membra {
namespace {

// A 30 x 30 mm sheet (or the disk `keep` leaves of it) stretched 1.3 x 1.2 with a stiff ellipse
// of epoxy, perturbed 0.1 mm (seed 1) and released in one step, free: it buckles.
Membrane biaxial_release(const NodeMask& keep = {}) {
  Membrane m = make_membrane(build_sheet({0.03, 0.03, 13, 13}, SheetOptions{}, keep));
  stretch_frame(m, 1.3, 1.2);
  impregnate(m, make_ellipse({0.0195, 0.018}, 0.008, 0.006, 0.0), epoxy(), +1, false);
  perturb(m, 1e-4, 1);
  begin_release(m);
  set_release_level(m, 0.0);
  return m;
}

// The largest difference of pairwise distances (a sample of pairs) between two forms: zero when
// they differ by a rigid motion only, m.
double pairwise_mismatch(const Points& a, const Points& b) {
  double worst = 0.0;
  for (Eigen::Index p = 0; p < a.cols(); p += 7)
    for (Eigen::Index q = 0; q < a.cols(); q += 5)
      worst =
          std::max(worst, std::abs((a.col(p) - a.col(q)).norm() - (b.col(p) - b.col(q)).norm()));
  return worst;
}

// A 50 x 50 mm sheet stretched 1.3 x 1.1 on its frame, every free particle moved by up to
// 0.2 mm (seed 5): near its stable minimum, the start of the quadratic-convergence tests.
Membrane perturbed_stretched_sheet() {
  Membrane m = make_membrane(build_sheet({0.05, 0.05, 11, 11}, SheetOptions{}));
  stretch_frame(m, 1.3, 1.1);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int p = 0; p < m.state.x.cols(); ++p)
    if (!m.sheet.model.pinned(p)) m.state.x.col(p) += 2e-4 * Vec3(u(rng), u(rng), u(rng));
  return m;
}

class NewtonHessian : public ::testing::TestWithParam<bool> {};

// With springs, and with bending alone (its entries are ~1e4x smaller than the springs', so
// checked on their own).
TEST_P(NewtonHessian, MatchesFiniteDifferencesOfTheForces) {
  SheetOptions o;
  o.stretch = o.shear = GetParam();
  Sheet sheet = build_sheet({0.02, 0.02, 5, 5}, o);
  Model m = sheet.model;
  for (auto& l0 : m.springs.rest_length) l0 *= 0.9;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Points x = m.reference;
  for (Eigen::Index i = 0; i < x.size(); ++i) x.data()[i] += 0.001 * u(rng);
  const Eigen::MatrixXd h = Eigen::MatrixXd(potential_hessian(m, x));
  const double step = 1e-7;
  double err = 0.0;
  for (Eigen::Index c = 0; c < x.size(); ++c) {
    Points xp = x, xm = x, fp, fm;
    xp.data()[c] += step;
    xm.data()[c] -= step;
    compute_static_forces(m, xp, fp);
    compute_static_forces(m, xm, fm);
    for (Eigen::Index r = 0; r < x.size(); ++r)
      err = std::max(err, std::abs(-(fp.data()[r] - fm.data()[r]) / (2 * step) - h(r, c)));
  }
  EXPECT_LT(err / h.cwiseAbs().maxCoeff(), 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Springs, NewtonHessian, ::testing::Values(true, false));

// A 100 x 10 mm strip coated on one face, stretched 1.5x along its length and released in five
// increments, turned in the plane by `degrees` before the release: Newton's gauge must remove
// only rigid motions in any orientation (held along the sheet's own axes it forbade a strip
// along y to shorten). The middle curls to Timoshenko's curvature within 3 %.
class NewtonGauge : public ::testing::TestWithParam<double> {};

TEST_P(NewtonGauge, ReleasedStripCurlsToTimoshenkoInAnyOrientation) {
  Membrane m = make_membrane(build_sheet({0.1, 0.01, 41, 5}, SheetOptions{}));
  stretch_frame(m, 1.5, 1.0);
  impregnate(m, make_polygon({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}), epoxy(), +1, true);
  begin_release(m);
  const double turn = GetParam() * std::acos(-1.0) / 180.0;
  m.state.x = Eigen::AngleAxisd(turn, Vec3::UnitZ()).toRotationMatrix() * m.state.x;
  NewtonOptions o;
  o.force_scale = m.sheet.stiffness.stretch * m.sheet.grid.hx();
  for (int k = 1; k <= 5; ++k) {
    set_release_level(m, 1.0 - k / 5.0);
    const SolveReport r = solve_newton(m.sheet.model, m.state, o);
    ASSERT_TRUE(r.converged) << GetParam() << " degrees, increment " << k << ": " << r.message;
  }
  const GridSheet& g = m.sheet.grid;
  const Points& x = m.state.x;
  const double curvature = circle_curvature(x.col(g.particle(10, 2)), x.col(g.particle(20, 2)),
                                            x.col(g.particle(30, 2)));
  const double expected = bilayer_curvature_per_strain(latex(), epoxy()) * (1.0 - 1.0 / 1.5);
  EXPECT_NEAR(curvature / expected, 1.0, 0.03) << GetParam() << " degrees";
}

INSTANTIATE_TEST_SUITE_P(Orientations, NewtonGauge, ::testing::Values(0.0, 90.0, 30.0, 45.0));

// A path's increments solved with a NewtonCache (a path's setup kept from one solve to the
// next) end exactly where they end without one, bit for bit, with fewer setups; a model with
// other elements, or other free coordinates, is set up anew. Each increment solves its own copy
// of the model, freed after: a kept setup that read an earlier model than the present one would
// read freed memory (the sanitized suite sees it).
TEST(Newton, ACacheKeepsTheSetupNotTheResults) {
  Membrane m = make_membrane(build_sheet({0.1, 0.01, 41, 5}, SheetOptions{}));
  stretch_frame(m, 1.5, 1.0);
  impregnate(m, make_polygon({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}), epoxy(), +1, true);
  begin_release(m);
  const State start = m.state;
  NewtonOptions o;
  o.force_scale = m.sheet.stiffness.stretch * m.sheet.grid.hx();
  long setups[2] = {0, 0}, iterations[2] = {0, 0};
  Points end[2];
  for (const int cached : {0, 1}) {
    m.state = start;
    o.cache = cached ? make_newton_cache() : nullptr;
    for (int k = 1; k <= 5; ++k) {
      set_release_level(m, 1.0 - k / 5.0);
      const auto copy = std::make_unique<const Model>(m.sheet.model);
      const SolveReport r = solve_newton(*copy, m.state, o);
      ASSERT_TRUE(r.converged) << r.message;
      setups[cached] += r.setups;
      iterations[cached] += r.iterations;
    }
    end[cached] = m.state.x;
  }
  EXPECT_EQ(setups[0], 5);
  EXPECT_LT(setups[1], 5);
  EXPECT_GE(setups[1], 1);
  EXPECT_EQ(iterations[0], iterations[1]);
  EXPECT_TRUE(end[0] == end[1]) << "largest difference " << (end[0] - end[1]).cwiseAbs().maxCoeff();
  // Other elements (a spring fewer): the cached setup does not fit and is replaced.
  Model fewer = m.sheet.model;
  std::vector<bool> keep(static_cast<size_t>(fewer.springs.size()), true);
  keep.back() = false;
  fewer.springs.filter(keep);
  State s = m.state;
  EXPECT_EQ(solve_newton(fewer, s, o).setups, 1);
  EXPECT_EQ(solve_newton(fewer, s, o).setups, 0);
  // The same elements with a particle pinned: other free coordinates.
  fewer.inv_mass[0] = 0.0;
  EXPECT_EQ(solve_newton(fewer, s, o).setups, 1);
}

// A square and a disk with a stiff disc in the middle, stretched biaxially and released (free,
// so held by the gauge; both perturbed alike, 0.1 mm, seed 1): Newton and the static solver end
// in the same buckled form (the energy within
// 1e-6 relative, the positions within 1e-4 of the size up to a rigid motion).
TEST(Newton, AgreesWithTheStaticSolverOnBiaxialReleases) {
  for (const bool disk : {false, true}) {
    NodeMask keep;
    if (disk)
      keep = [](double u, double v) { return std::hypot(u - 0.015, v - 0.015) <= 0.015 + 1e-9; };
    Membrane m = biaxial_release(keep);
    const double k = m.sheet.stiffness.stretch, scale = k * m.sheet.grid.hx();
    State a = m.state, b = m.state;
    NewtonOptions no;
    no.force_scale = scale;
    no.tolerance = 1e-9;
    ASSERT_TRUE(solve_newton(m.sheet.model, a, no).converged);
    StaticOptions so;
    so.force_scale = scale;
    so.tolerance = 1e-9;
    ASSERT_TRUE(solve_static(m.sheet.model, b, so).converged);
    const double ea = potential_energy(m.sheet.model, a.x),
                 eb = potential_energy(m.sheet.model, b.x);
    EXPECT_NEAR(ea / eb, 1.0, 1e-6) << (disk ? "disk" : "square");
    EXPECT_LT(pairwise_mismatch(a.x, b.x), 1e-4 * 0.03) << (disk ? "disk" : "square");
  }
}

// Near a minimum Newton converges quadratically: once the residual is small, each iteration
// squares it (ratio r_{k+1} / r_k^2 bounded, in units of the force scale) until round-off.
TEST(Newton, ConvergesQuadraticallyNearAMinimum) {
  Membrane m = perturbed_stretched_sheet();
  NewtonOptions o;
  o.force_scale = m.sheet.stiffness.stretch * m.sheet.grid.hx();
  o.tolerance = 1e-13;
  std::vector<double> residuals;
  o.progress = [&](const Progress& p) { residuals.push_back(p.residual_relative); };
  EXPECT_TRUE(solve_newton(m.sheet.model, m.state, o).converged);
  for (double r : residuals) std::printf("%.3g ", r);
  std::printf("\n");
  // Squaring, down to a round-off floor of 1e-12 of the force scale.
  int quadratic = 0;
  for (size_t k = 0; k + 1 < residuals.size(); ++k)
    if (residuals[k] < 1e-2 && residuals[k] > 1e-10) {
      EXPECT_LT(residuals[k + 1], std::max(10.0 * residuals[k] * residuals[k], 1e-12))
          << "iteration " << k;
      ++quadratic;
    }
  EXPECT_GE(quadratic, 2);  // at least two squaring steps were seen
}

// A flat sheet squeezed on its frame is an exact equilibrium with zero force, but a saddle:
// Newton must leave it along negative curvature and end buckled in a stable minimum, never
// report the flat saddle as converged.
TEST(Newton, EscapesTheSaddleOfACompressedFlatSheet) {
  Membrane m = make_membrane(build_sheet({0.05, 0.05, 11, 11}, SheetOptions{}));
  stretch_frame(m, 0.9, 0.9);
  const double k = m.sheet.stiffness.stretch;
  ASSERT_FALSE(check_stability(m.sheet.model, m.state.x, k).stable);
  NewtonOptions o;
  o.force_scale = k * m.sheet.grid.hx();
  const SolveReport r = solve_newton(m.sheet.model, m.state, o);
  EXPECT_TRUE(r.converged) << r.message;
  EXPECT_GE(r.negative_curvature_steps, 1);
  EXPECT_FALSE(r.saddle);
  const double rise = m.state.x.row(2).cwiseAbs().maxCoeff();
  EXPECT_GT(rise, 0.05 * 0.045);  // buckled: several mm on a 45 mm frame
  EXPECT_TRUE(check_stability(m.sheet.model, m.state.x, k).stable);
}

// Pseudo-transient continuation (the bench-only solver "ptc", NewtonOptions::continuation)
// follows the same energy downhill by implicit-Euler steps: on the square of the biaxial
// agreement test it must end in Newton's buckled minimum (energy within 1e-6 relative, positions
// within 1e-4 of the size up to a rigid motion), a stable one.
TEST(Continuation, EndsInNewtonsMinimumOnABiaxialRelease) {
  Membrane m = biaxial_release();
  const double k = m.sheet.stiffness.stretch;
  NewtonOptions o;
  o.force_scale = k * m.sheet.grid.hx();
  o.tolerance = 1e-9;
  o.max_iterations = 5000;
  State newton = m.state, ptc = m.state;
  ASSERT_TRUE(solve_newton(m.sheet.model, newton, o).converged);
  o.continuation = true;
  const SolveReport r = solve_newton(m.sheet.model, ptc, o);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_EQ(r.negative_curvature_steps, 0);  // continuation never takes Newton's saddle steps
  EXPECT_NEAR(potential_energy(m.sheet.model, ptc.x) / potential_energy(m.sheet.model, newton.x),
              1.0, 1e-6);
  EXPECT_LT(pairwise_mismatch(ptc.x, newton.x), 1e-4 * 0.03);
  EXPECT_TRUE(check_stability(m.sheet.model, ptc.x, k).stable);
}

// Its shift falls with the residual (switched evolution relaxation), so near a minimum its steps
// become Newton's and square the residual: on a perturbed stretched sheet, at least two
// iterations with r_{k+1} < 10 r_k^2 once r_k < 1e-2 (in units of the force scale).
TEST(Continuation, BecomesNewtonNearAMinimum) {
  Membrane m = perturbed_stretched_sheet();
  NewtonOptions o;
  o.continuation = true;
  o.force_scale = m.sheet.stiffness.stretch * m.sheet.grid.hx();
  o.tolerance = 1e-13;
  std::vector<double> residuals;
  o.progress = [&](const Progress& p) { residuals.push_back(p.residual_relative); };
  const SolveReport r = solve_newton(m.sheet.model, m.state, o);
  EXPECT_TRUE(r.converged) << r.message;
  int quadratic = 0;
  for (size_t k = 0; k + 1 < residuals.size(); ++k)
    if (residuals[k] < 1e-2 && residuals[k] > 1e-10 &&
        residuals[k + 1] < std::max(10.0 * residuals[k] * residuals[k], 1e-12))
      ++quadratic;
  EXPECT_GE(quadratic, 2);
}

}  // namespace
}  // namespace membra
