// Darts (design/dart_layout.hpp): the target's circumferential deficit against a sphere's closed
// form, and darts as wide as that deficit asks.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "membra/design/dart_layout.hpp"
#include "membra/measure/curvature.hpp"

namespace membra {
namespace {

constexpr double kPi = std::numbers::pi;

TargetSurface analytic(const char* kind, double size, double height) {
  TargetSpec spec;
  spec.kind = kind;
  spec.size = size;
  spec.height = height;
  return make_target(spec);
}

// The bundled cap: 160 mm across, 24 mm high, a sphere of radius 145.3 mm.
TargetSurface cap() {
  return analytic("cap", 0.16, 0.024);
}

// Six darts about the cap on a 170 mm frame stretched 1.15, at 1.2 times the deficit: the
// layout two tests cut.
const Box2 cap_frame{Vec2::Zero(), Vec2(0.17, 0.17)};
DartOptions six_cap_darts() {
  DartOptions o;
  o.darts = 6;
  o.scale = 1.2;
  o.lambda = 1.15;
  return o;
}

double sphere_radius() {
  return (0.08 * 0.08 + 0.024 * 0.024) / (2.0 * 0.024);
}

// On a sphere of radius R a circle at geodesic distance s from the pole is 2 pi R sin(s/R) long:
// the deficit is 1 - R sin(s/R) / s, 5.6 % at the cap's rim. The profile, read off the target's
// triangle mesh (41 vertices across), follows it to 1e-3 on every ray.
TEST(DartLayout, ACapsDeficitIsItsSpheres) {
  const DartProfile p = dart_profile(cap());
  const double R = sphere_radius(), rim = R * std::asin(0.08 / R);
  EXPECT_NEAR(p.radius, rim, 2e-3 * rim);
  for (double theta : {0.0, 0.7, 2.0, 4.1})
    for (double u : {0.25, 0.5, 0.75, 1.0}) {
      const double s = u * rim;
      EXPECT_NEAR(p.at(theta, u), 1.0 - R * std::sin(s / R) / s, 1e-3) << theta << " " << u;
    }
}

// A paraboloid z = -a r^2 about its apex is a surface of revolution: its circles are 2 pi rho long
// and its length from the apex s(rho) = (rho sqrt(1 + k^2 rho^2) + asinh(k rho) / k) / 2 with
// k = 2a (here a = 0.002 /mm, k = 4 /m).
double paraboloid_length(double rho) {
  constexpr double k = 4.0;
  return 0.5 * (rho * std::sqrt(1.0 + k * k * rho * rho) + std::asinh(k * rho) / k);
}

// Its deficit 1 - rho / s at u of the length along the surface of a ray ending at rho_end.
double paraboloid_deficit(double rho_end, double u) {
  double lo = 0.0, hi = rho_end;  // find rho with s(rho) = u s(rho_end)
  for (int i = 0; i < 60; ++i)
    (paraboloid_length(0.5 * (lo + hi)) < u * paraboloid_length(rho_end) ? lo : hi) =
        0.5 * (lo + hi);
  const double rho = 0.5 * (lo + hi);
  return 1.0 - rho / paraboloid_length(rho);
}

// The paraboloid over a square: the deficit follows the closed form to the footprint's edge,
// along an axis and along a diagonal (1.4 % and 2.8 % there), where the sideways samples must
// stay on the footprint.
TEST(DartLayout, ASquareDomesDeficitReachesItsEdges) {
  TargetSpec spec;
  spec.kind = "height_field";
  spec.size = 0.15;
  spec.formula = "-0.002*(x^2+y^2)";
  const DartProfile p = dart_profile(make_target(spec));
  for (double theta : {0.0, 0.25 * kPi})
    for (double u : {0.5, 1.0}) {
      const double rho_end = 0.075 / std::max(std::cos(theta), std::sin(theta)) * (1.0 - 4e-3);
      EXPECT_NEAR(p.at(theta, u), paraboloid_deficit(rho_end, u), 1e-3) << theta << " " << u;
    }
}

// The same paraboloid with its apex 30 mm along x, its profile taken about the apex: each ray
// runs to the footprint's edge from there (45, 75 and 105 mm along x, y and -x, less the rim's
// margin) and the deficit is the closed form's on each.
TEST(DartLayout, AnOffCentreProfileRunsToTheFootprintsEdge) {
  TargetSpec spec;
  spec.kind = "height_field";
  spec.size = 0.15;
  spec.formula = "-0.002*((x-30)^2+y^2)";
  const TargetSurface t = make_target(spec);
  const DartProfile p = dart_profile(t, Vec2(0.03, 0.0));
  EXPECT_NEAR(p.centre.x(), 0.03, 1e-12);
  for (const auto& [theta, edge] : {std::pair{0.0, 0.045}, {0.5 * kPi, 0.075}, {kPi, 0.105}}) {
    const double rho_end = edge * (1.0 - 4e-3), s_end = paraboloid_length(rho_end);
    EXPECT_NEAR(p.s[static_cast<size_t>(std::lround(theta / (2.0 * kPi) * p.rays))].back(), s_end,
                2e-3 * s_end)
        << theta;
    for (double u : {0.5, 1.0})
      EXPECT_NEAR(p.at(theta, u), paraboloid_deficit(rho_end, u), 1e-3) << theta << " " << u;
  }
}

// Two domes side by side, darts about each apex: each centre's darts stay on its side of the
// bisector, min_feature / 2 short of it, and each centre gets some.
TEST(DartLayout, EachCentresDartsStayInItsCell) {
  TargetSpec spec;
  spec.kind = "height_field";
  spec.size = 0.15;
  spec.formula = "20*exp(-((x-40)^2+y^2)/1800) + 20*exp(-((x+40)^2+y^2)/1800)";
  const TargetSurface t = make_target(spec);
  const std::vector<DartProfile> p = {dart_profile(t, Vec2(-0.04, 0.0)),
                                      dart_profile(t, Vec2(0.04, 0.0))};
  DartOptions o;
  o.darts = 4;
  o.lambda = 1.1;
  const Box2 frame{Vec2::Zero(), Vec2(0.155, 0.155)};
  const Stencil st = layout_darts(p, frame, false, o);
  ASSERT_EQ(st.spec.kind, PatternSpec::Kind::difference);
  int left = 0, right = 0;
  const double middle = 0.0775, margin = 0.5 * o.min_feature;
  const Vec2 left_centre(middle - 0.04 * 155.0 / 150.0, middle);
  const Vec2 right_centre(middle + 0.04 * 155.0 / 150.0, middle);
  for (size_t i = 1; i < st.spec.parts.size(); ++i) {
    const auto& pts = st.spec.parts[i].points;
    // The dart's own centre: the one its tip (its vertex nearest either centre) is nearest to.
    double to_left = 1e9, to_right = 1e9;
    for (const Vec2& q : pts) {
      to_left = std::min(to_left, (q - left_centre).norm());
      to_right = std::min(to_right, (q - right_centre).norm());
    }
    const bool is_left = to_left < to_right;
    (is_left ? left : right) += 1;
    for (const Vec2& q : pts)
      EXPECT_TRUE(is_left ? q.x() <= middle - margin + 1e-9 : q.x() >= middle + margin - 1e-9)
          << q.transpose();
  }
  EXPECT_GT(left, 0);
  EXPECT_GT(right, 0);
  EXPECT_LT(st.resin_share, 0.95);
}

// Darts through a coat on two faces: with a face per cell (here the left half on top, the right
// underneath) the resin splits into a top part and a bottom part, the cells of each face on it,
// and a dart is bare latex on both; the resin share counts both faces.
TEST(DartLayout, DartsCutThroughACoatOnEitherFace) {
  const DartProfile p = dart_profile(cap());
  const Box2& frame = cap_frame;
  DartOptions o = six_cap_darts();
  const Stencil one = layout_darts({p}, frame, true, o);
  o.face = [](const Vec2& q) { return q.x() < 0.085 ? +1 : -1; };
  o.cell = 0.017;
  const Stencil two = layout_darts({p}, frame, true, o);
  ASSERT_TRUE(two.pattern && two.pattern_bottom);
  EXPECT_EQ(two.pieces, 2);
  EXPECT_EQ(two.pieces_bottom(), 1);
  EXPECT_NEAR(two.resin_share, one.resin_share, 1e-9);
  int checked = 0;
  for (int j = 0; j < 40; ++j)
    for (int i = 0; i < 40; ++i) {
      const Vec2 q = frame.min + 0.17 * Vec2((i + 0.5) / 40, (j + 0.5) / 40);
      if ((q - Vec2(0.085, 0.085)).norm() > 0.08) continue;
      const bool resin = one.pattern->contains(q);
      EXPECT_EQ(two.pattern->contains(q), resin && q.x() < 0.085) << q.transpose();
      EXPECT_EQ(two.pattern_bottom->contains(q), resin && q.x() >= 0.085) << q.transpose();
      checked += resin ? 0 : 1;
    }
  EXPECT_GT(checked, 20);  // points in darts were among them
  // Off the disk (the frame's corners) neither face has resin.
  for (const Vec2& q :
       {Vec2(0.005, 0.005), Vec2(0.165, 0.005), Vec2(0.165, 0.165), Vec2(0.005, 0.165)})
    EXPECT_FALSE(two.pattern->contains(q) || two.pattern_bottom->contains(q)) << q.transpose();
  o.face = [](const Vec2&) { return -1; };  // all underneath: one part, on the bottom
  const Stencil under = layout_darts({p}, frame, true, o);
  EXPECT_FALSE(under.pattern);
  EXPECT_TRUE(under.pattern_bottom);
}

// "dart_centres": "auto": the free form's two bumps and its valley's middle are peaks of its
// Gaussian curvature (within 5 mm of where the formula puts them; a fourth, weaker one sits at a
// valley's end), highest first; a sphere's cap and a paraboloid, whose curvature is even or
// nearly so, have none.
TEST(DartLayout, CurvaturePeaksFindTheBumpsAndNotASpheresEvenCurvature) {
  TargetSpec spec;
  spec.kind = "height_field";
  spec.size = 0.15;
  spec.formula =
      "12*exp(-((x-35)^2+(y-20)^2)/800) + 10*exp(-((x+35)^2+(y+25)^2)/800) - "
      "6*exp(-((x-y)^2)/1000)";
  const std::vector<Vec2> peaks = curvature_peaks(make_target(spec), 0.03);
  ASSERT_GE(peaks.size(), 3u);
  EXPECT_LE(peaks.size(), 4u);
  // K at the bumps' tops (from the formula, grid of 1 mm): 7.8e-4 and 4.1e-4 at (40, 15) and
  // (-41, -19); 3.4e-4 at the valley's middle.
  const std::vector<Vec2> expected = {{0.040, 0.015}, {-0.041, -0.019}, {0.0, 0.0}};
  for (const Vec2& e : expected) {
    double nearest = 1.0;
    for (const Vec2& p : peaks) nearest = std::min(nearest, (p - e).norm());
    EXPECT_LT(nearest, 0.005) << e.transpose();
  }
  EXPECT_LT((peaks.front() - expected.front()).norm(), 0.005);  // the highest first
  EXPECT_TRUE(curvature_peaks(cap(), 0.03).empty());
  spec.formula = "-0.002*(x^2+y^2)";
  EXPECT_TRUE(curvature_peaks(make_target(spec), 0.03).empty());
}

// A plane asks for no shrink: no darts, the whole sheet is resin.
TEST(DartLayout, APlaneGetsNoDarts) {
  TargetSpec spec;
  spec.kind = "height_field";
  spec.size = 0.15;
  spec.formula = "0";
  const TargetSurface plane = make_target(spec);
  const DartProfile p = dart_profile(plane);
  for (double u : {0.3, 1.0}) EXPECT_NEAR(p.at(0.5, u), 0.0, 1e-9);
  const Stencil s = layout_darts({p}, {Vec2::Zero(), Vec2(0.15, 0.15)}, false, {});
  EXPECT_DOUBLE_EQ(s.resin_share, 1.0);
}

// The latex share of a circle of frame radius r is the scale times the deficit there over the
// latex's shrink 1 - 1/lambda; where that makes a dart narrower than the minimum feature, the
// circle is all resin.
TEST(DartLayout, DartsAreAsWideAsTheDeficitAsks) {
  const DartProfile p = dart_profile(cap());
  const DartOptions o = six_cap_darts();
  const Stencil s = layout_darts({p}, cap_frame, true, o);
  const Vec2 c(0.085, 0.085);
  const auto latex_share = [&](double r) {
    constexpr int n = 3600;
    int latex = 0;
    for (int i = 0; i < n; ++i) {
      const double t = 2.0 * kPi * (i + 0.5) / n;
      latex += s.pattern->contains(c + r * Vec2(std::cos(t), std::sin(t))) ? 0 : 1;
    }
    return static_cast<double>(latex) / n;
  };
  for (double u : {0.6, 0.8, 0.95}) {
    const double asked = o.scale * p.at(0.0, u) / (1.0 - 1.0 / o.lambda);
    EXPECT_NEAR(latex_share(u * 0.085), asked, 0.02 * asked + 0.005) << u;
  }
  // Near the centre the darts would be narrower than 4 mm: none there.
  EXPECT_EQ(latex_share(0.01), 0.0);
  EXPECT_GT(s.resin_share, 0.6);
  EXPECT_LT(s.resin_share, 0.9);
}

// The bundled saddle: z = h (x^2 - y^2) / (s/2)^2, 150 mm square, h = 15 mm.
TargetSurface saddle() {
  return analytic("saddle", 0.15, 0.015);
}

// Rows along x of a saddle must be longer at its edges than through its middle: L'' = -K L with
// K < 0 makes L = cosh(sqrt(-K) v) for a uniform K. The share of latex a row asks is
// 1 - L / L_max: largest through the middle, none at the edges, symmetric; through the middle
// it is 1 - 1 / cosh(sqrt(-K) s/2) for the saddle's mean K, within 15 % (its K is not uniform:
// -4c^2 at the centre, about a quarter less at the edges' middles, so the middle rows ask a little
// more).
TEST(DartLayout, ASaddlesRowsAreLongerAtItsEdges) {
  const TargetSurface t = saddle();
  const RowProfile p = row_profile(t, 0);
  ASSERT_EQ(p.v.size(), 25u);
  const GaussianCurvature k = gaussian_curvature(t.x, t.triangles);
  double defect = 0.0, area = 0.0;
  for (size_t i = 0; i < k.interior.size(); ++i)
    if (k.interior[i]) defect += k.angle_defect[i], area += k.area[i];
  ASSERT_LT(defect, 0.0);
  const double expected = 1.0 - 1.0 / std::cosh(std::sqrt(-defect / area) * 0.075);
  const double middle = p.share[12];
  EXPECT_NEAR(p.v[12], 0.0, 1e-12);
  EXPECT_NEAR(middle, expected, 0.15 * expected);
  EXPECT_LT(p.share.front(), 0.05 * middle);
  for (size_t i = 0; i < p.v.size(); ++i) EXPECT_NEAR(p.share[i], p.share[24 - i], 1e-9);
  for (size_t i = 1; i <= 12; ++i) EXPECT_GT(p.share[i], p.share[i - 1]);
  // A dome's rows are the other way round: longest through the middle.
  const RowProfile dome = row_profile(cap(), 0);
  EXPECT_LT(dome.share[12], 1e-3);
  EXPECT_GT(dome.share.front(), 0.02);
}

// Fisheye darts across the stretch: the latex share of the middle row is the scale times the
// share asked over 1 - 1/lambda; every lens is at least the minimum feature wide.
TEST(DartLayout, FisheyeDartsShortenTheRowsAsAsked) {
  const RowProfile p = row_profile(saddle(), 0);
  const Box2 frame{Vec2::Zero(), Vec2(0.155, 0.155)};
  DartOptions o;
  o.darts = 3;
  o.scale = 0.6;
  o.lambda = 1.1;
  const Stencil s = layout_fisheye_darts(p, frame, o);
  const auto latex_share = [&](double y) {
    constexpr int n = 3100;
    int latex = 0;
    for (int i = 0; i < n; ++i)
      latex += s.pattern->contains(Vec2(0.155 * (i + 0.5) / n, y)) ? 0 : 1;
    return static_cast<double>(latex) / n;
  };
  const double asked = o.scale * p.share[12] / (1.0 - 1.0 / o.lambda);
  EXPECT_NEAR(latex_share(0.0775), asked, 0.03 * asked);
  const auto& parts = s.spec.parts;
  ASSERT_EQ(parts.size(), 4u);  // the sheet and three lenses
  for (size_t i = 1; i < parts.size(); ++i) {
    const std::vector<Vec2>& q = parts[i].points;
    const size_t half = q.size() / 2;  // left side up, right side down
    for (size_t j = 0; j < half; ++j) EXPECT_GE(q[q.size() - 1 - j].x() - q[j].x(), 0.004 - 1e-6);
  }
}

}  // namespace
}  // namespace membra
