// The global form's Gaussian curvature: wrinkles and waves average out of its positive and
// negative parts, its total is the global form's own.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "membra/measure/global_curvature.hpp"
#include "membra/measure/paper_windows.hpp"
#include "membra/measure/shape.hpp"
#include "membra/model/sheet.hpp"

namespace membra {
namespace {

// A 200 mm sheet of n x n particles shaped by z(u, v) (u, v from its centre, m).
template <typename Height>
Points shaped(const Sheet& s, Height z) {
  Points x = s.model.reference;
  for (Eigen::Index p = 0; p < x.cols(); ++p) x(2, p) = z(x(0, p) - 0.1, x(1, p) - 0.1);
  return x;
}

// A bowl (z = (x^2 + y^2) / 2R) and a saddle (z = (x^2 - y^2) / 2R), each corrugated by
// wrinkles along x, 10 mm apart and 1 mm high, on a 200 mm sheet: the raw angle defects are the
// wrinkles' (both signs alike, "folded"); the global form's read as the bowl and the saddle.
std::pair<std::string, std::string> corrugated_forms(double sign) {
  const Sheet s = build_sheet({0.2, 0.2, 81, 81}, SheetOptions{});
  const double r = 0.15, a = 1.0e-3, k = 2.0 * std::numbers::pi / 0.01;
  const Points x = shaped(s, [&](double u, double v) {
    return (u * u + sign * v * v) / (2.0 * r) + a * std::sin(k * v);
  });
  GaussianCurvature raw = gaussian_curvature(x, s.triangles);
  smooth_density_on_grid(s.grid, raw);
  const GaussianCurvature global = global_curvature(x, s.model.reference, s.triangles);
  std::printf("%s: raw +%.2f %.2f, global +%.2f %.2f rad\n", sign > 0 ? "bowl" : "saddle",
              raw.positive, raw.negative, global.positive, global.negative);
  return {classify_form(raw), classify_form(global)};
}

// On a fine grid (301^2, where a window holds thousands of particles) a bowl with short, steep
// wrinkles (3 spacings long, across v) keeps its curvature in the global density: the angle
// defects of a window sum to what its rim turns (Gauss-Bonnet), so the wrinkles cancel only when
// every particle of the window is summed.
TEST(GlobalCurvature, AFinelyWrinkledBowlOnAFineGridReadsAsTheBowl) {
  const Sheet s = build_sheet({0.2, 0.2, 301, 301}, SheetOptions{});
  const double r = 0.15, a = 0.2e-3, k = 2.0 * std::numbers::pi / 0.002;
  const Points x = shaped(
      s, [&](double u, double v) { return (u * u + v * v) / (2.0 * r) + a * std::sin(k * v); });
  const GaussianCurvature global = global_curvature(x, s.model.reference, s.triangles);
  std::printf("fine bowl: global +%.3f %.3f rad, total %.3f\n", global.positive, global.negative,
              global.total);
  {
    const Points g = global_form(x, s.model.reference);
    // A window of radius R lifts a paraboloid's mean by R^2 / 4r.
    const double window = window_radius(x, s.model.reference);
    const double lift = window * window / (4.0 * r);
    double worst = 0.0;
    for (Eigen::Index p = 0; p < x.cols(); ++p) {
      const double u = x(0, p) - 0.1, v = x(1, p) - 0.1;
      if (std::abs(u) > 0.07 || std::abs(v) > 0.07) continue;
      worst = std::max(worst, std::abs(g(2, p) - (u * u + v * v) / (2.0 * r) - lift));
    }
    std::printf("fine bowl: global form off the smooth bowl by %.3g m at most\n", worst);
    // The windows' means are the smooth bowl's, lifted by the window's smoothing (0.26 mm): the
    // wrinkles (0.2 mm high) do not alias into them (from windows thinned 2-fold: 8 um).
    EXPECT_LT(worst, 0.02e-3);
  }
  EXPECT_EQ(classify_form(global), "synclastic");
  // All of the global form's curvature is the bowl's, positive: the windows' positive part is
  // its total (a window thinned to every other particle read +0.94 against 1.20 rad).
  EXPECT_GT(global.negative, -0.05 * global.positive);
  EXPECT_NEAR(global.positive, global.total, 0.05 * global.total);
}

// The same wrinkled bowl (wrinkles 1.5 mm long, their height varying along u) on a grid whose
// windows are whole (161^2) and on one whose windows hold 8 times more particles than PaperWindows
// takes (513^2): the global form's total curvature and height agree within 1 %. (From thinned
// windows the 513^2 total read 1.43 rad against 1.20.)
TEST(GlobalCurvature, TheGlobalFormOfABigSheetIsTheSmallOnes) {
  double total[2], height[2];
  int k = 0;
  for (const int n : {161, 513}) {
    const Sheet s = build_sheet({0.2, 0.2, n, n}, SheetOptions{});
    const double r = 0.15, a = 0.3e-3, w = 2.0 * std::numbers::pi / 0.0015;
    const Points x = shaped(s, [&](double u, double v) {
      return (u * u + v * v) / (2.0 * r) + a * std::sin(w * v) * (1.0 + 0.5 * std::sin(37.0 * u));
    });
    total[k] = global_curvature(x, s.model.reference, s.triangles).total;
    height[k] = summarize_shape(x, s.model.reference).global_height;
    std::printf("%d^2: global total %.4f rad, global height %.3f mm\n", n, total[k],
                1e3 * height[k]);
    ++k;
  }
  EXPECT_NEAR(total[1] / total[0], 1.0, 0.01);
  EXPECT_NEAR(height[1] / height[0], 1.0, 0.01);
}

TEST(GlobalCurvature, ACorrugatedBowlIsSynclasticAndACorrugatedSaddleAnticlastic) {
  const auto [bowl_raw, bowl_global] = corrugated_forms(+1.0);
  EXPECT_EQ(bowl_global, "synclastic");
  EXPECT_NE(bowl_raw, "synclastic");
  const auto [saddle_raw, saddle_global] = corrugated_forms(-1.0);
  EXPECT_EQ(saddle_global, "anticlastic");
  EXPECT_NE(saddle_raw, "anticlastic");
}

// A bowl and a saddle (R = 150 mm) under an egg-crate of waves 50 mm long and up to 14 mm high,
// tapered to nothing at the edges (so the totals stay the bowl's and the saddle's: +1.19 and
// -1.15 rad). The waves, bumps and dips of both signs of curvature, are twice as long as the
// global form's window is wide, so the global form keeps a good part of them: averaged over the
// form's own window the density reads "folded" both times (+3.43 / -2.29 rad on the bowl); over
// the wider window of global_curvature the bumps and dips cancel (+1.97 / -0.77) and the bowl
// reads as a bowl, the saddle as a saddle. (Shorter waves average out of the global form itself,
// the corrugation above; with waves 18 mm high both averages read "folded".)
std::pair<GaussianCurvature, GaussianCurvature> egg_crate(double sign) {
  const Sheet s = build_sheet({0.2, 0.2, 65, 65}, SheetOptions{});
  const double k = 2.0 * std::numbers::pi / 0.05;
  const auto taper = [](double u) { return std::pow(std::cos(std::numbers::pi * u / 0.2), 2); };
  const Points x = shaped(s, [&](double u, double v) {
    return (u * u + sign * v * v) / 0.3 +
           14e-3 * std::sin(k * u) * std::sin(k * v) * taper(u) * taper(v);
  });
  const Points& paper = s.model.reference;
  GaussianCurvature narrow = gaussian_curvature(global_form(x, paper), s.triangles);
  average_density_over_windows(paper, window_radius(x, paper), narrow);
  const GaussianCurvature wide = global_curvature(x, paper, s.triangles);
  std::printf("%s: form's window +%.2f %.2f (%s), twice it +%.2f %.2f (%s), total %.3f rad\n",
              sign > 0 ? "bowl" : "saddle", narrow.positive, narrow.negative,
              classify_form(narrow).c_str(), wide.positive, wide.negative,
              classify_form(wide).c_str(), wide.total);
  return {narrow, wide};
}

TEST(GlobalCurvature, WavesAsLongAsTheWindowCancelOutOfABowlAndASaddle) {
  const auto [bowl_narrow, bowl] = egg_crate(+1.0);
  EXPECT_EQ(classify_form(bowl_narrow), "folded");
  EXPECT_EQ(classify_form(bowl), "synclastic");
  // The averaging moves the density, not the angle defects: the total is the global form's.
  EXPECT_DOUBLE_EQ(bowl.total, bowl_narrow.total);
  const auto [saddle_narrow, saddle] = egg_crate(-1.0);
  EXPECT_EQ(classify_form(saddle_narrow), "folded");
  EXPECT_EQ(classify_form(saddle), "anticlastic");
}

// On a sphere the density is 1/R^2 everywhere, and an average of a constant is the constant:
// within 3 % at every interior vertex a window away from the rim.
TEST(GlobalCurvature, ASphereKeepsItsCurvature) {
  const Sheet s = build_sheet({0.2, 0.2, 41, 41}, SheetOptions{});
  const double r = 0.3;
  const Points x =
      shaped(s, [&](double u, double v) { return r - std::sqrt(r * r - u * u - v * v); });
  const GaussianCurvature k = global_curvature(x, s.model.reference, s.triangles);
  ASSERT_EQ(k.density.size(), static_cast<size_t>(x.cols()));
  int checked = 0;
  for (Eigen::Index p = 0; p < x.cols(); ++p) {
    const double u = s.model.reference(0, p) - 0.1, v = s.model.reference(1, p) - 0.1;
    if (std::max(std::abs(u), std::abs(v)) > 0.05) continue;
    EXPECT_NEAR(k.density[static_cast<size_t>(p)] * r * r, 1.0, 0.03) << p;
    ++checked;
  }
  EXPECT_GT(checked, 300);
  EXPECT_EQ(classify_form(k), "synclastic");
}

TEST(GlobalCurvature, NoPaperNoCurvature) {
  const Sheet s = build_sheet({0.2, 0.2, 5, 5}, SheetOptions{});
  EXPECT_TRUE(global_curvature(s.model.reference, Points(), s.triangles).interior.empty());
  GaussianCurvature k = gaussian_curvature(s.model.reference, s.triangles);
  EXPECT_THROW(average_density_over_windows(Points(3, 4), 0.01, k), std::invalid_argument);
  EXPECT_THROW(average_density_over_windows(s.model.reference, 0.0, k), std::invalid_argument);
}

}  // namespace
}  // namespace membra
