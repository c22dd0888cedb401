// The continuum sheet's bending (model/elements/shell_triangles.hpp): Kirchhoff's plate energy on
// cylinders, spheres and saddles for the plate's own Poisson ratio, a bounded energy, finite
// differences and the composite rule across a resin edge.
#include "membra/model/elements/shell_triangles.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "element_checks.hpp"

namespace membra {
namespace {

constexpr double kD = 1.5e6 * 1.25e-10 / 9.0;  // N m: latex, E t^3 / (12 (1 - nu^2)), nu 1/2

// The patch bent into a cylinder (about y), a sphere and a saddle of radius r, lengths kept on
// the cylinder and the sphere.
struct Bent {
  Points cylinder, sphere, saddle;
};

Bent bend(const Points& flat, double r) {
  Bent b{flat, flat, flat};
  const Vec3 centre = flat.rowwise().mean();
  for (int p = 0; p < flat.cols(); ++p) {
    const Vec3 d = flat.col(p) - centre;
    b.cylinder(0, p) = centre.x() + r * std::sin(d.x() / r);
    b.cylinder(2, p) = r * (1.0 - std::cos(d.x() / r));
    const double rho = d.norm(), phi = rho / r, s = rho > 0.0 ? std::sin(phi) / rho : 1.0 / r;
    b.sphere.col(p) = centre + Vec3(r * s * d.x(), r * s * d.y(), r * (1.0 - std::cos(phi)));
    b.saddle(2, p) = (d.x() * d.x() - d.y() * d.y()) / (2.0 * r);
  }
  return b;
}

// The area of the triangles whose three edges are interior: there the mid-edge normals see the
// surface on both sides; a rim triangle's free edge reads no curvature across it.
double interior_area(const ShellTriangles& s) {
  double a = 0.0;
  for (int i = 0; i < s.size(); ++i) {
    const auto& n = s.neighbour[static_cast<size_t>(i)];
    if (n[0] >= 0 && n[1] >= 0 && n[2] >= 0) a += s.latex[static_cast<size_t>(i)].area;
  }
  return a;
}

// Kirchhoff's plate stores (D/2)(k1^2 + k2^2 + 2 nu k1 k2) per unit area: on a cylinder 1, on a
// sphere 2 (1 + nu), on a saddle 2 (1 - nu) times (D/2)/r^2. The interior triangles store that
// within 2 % for nu 1/2 (latex) and 1/3 (resin), in any orientation of the mesh, at two radii.
TEST(ShellTriangles, CylindersSpheresAndSaddlesStoreKirchhoffsPlateEnergy) {
  for (double nu : {0.5, 1.0 / 3.0})
    for (double angle : {0.0, 0.3, 1.2}) {
      const TriPatch m = tri_patch(24, 0.002, angle);
      ShellTriangles s;
      s.add_mesh(m.triangles, m.x, kD, nu);
      // Only the interior triangles: a copy whose rim triangles store nothing.
      ShellTriangles inner = s;
      for (int i = 0; i < inner.size(); ++i) {
        const auto& n = inner.neighbour[static_cast<size_t>(i)];
        if (n[0] < 0 || n[1] < 0 || n[2] < 0) inner.latex[static_cast<size_t>(i)].area = 0.0;
      }
      inner.invalidate();
      const double area = interior_area(s);
      for (double r : {0.4, 1.0}) {  // the saddle, a graph, is not isometric: r >> the patch
        const Bent b = bend(m.x, r);
        const double unit = 0.5 * kD / (r * r) * area;
        EXPECT_NEAR(set_energy(inner, b.cylinder) / unit, 1.0, 0.02) << nu << " " << angle;
        EXPECT_NEAR(set_energy(inner, b.sphere) / unit / (2.0 * (1.0 + nu)), 1.0, 0.02)
            << nu << " " << angle << " " << r;
        EXPECT_NEAR(set_energy(inner, b.saddle) / unit / (2.0 * (1.0 - nu)), 1.0, 0.02)
            << nu << " " << angle << " " << r;
      }
      EXPECT_NEAR(set_energy(s, m.x), 0.0, 1e-30);  // flat
      Points sheared = m.x;
      sheared.row(0) += 0.3 * m.x.row(1);
      EXPECT_NEAR(set_energy(s, sheared), 0.0, 1e-30);  // flat, however sheared in its plane
    }
}

// A square grid cut into right triangles, the other mesh family besides the equilateral one:
// the plate's energies hold there too, within 3 %.
TEST(ShellTriangles, OnAGridOfRightTrianglesTheyStoreThePlateEnergyToo) {
  constexpr int n = 24;
  const double h = 0.002;
  TriPatch m;
  m.x = Points::Zero(3, (n + 1) * (n + 1));
  auto id = [](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.x.col(id(i, j)) = Vec3(i * h, j * h, 0.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  ShellTriangles s;
  s.add_mesh(m.triangles, m.x, kD, 0.5);
  ShellTriangles inner = s;
  for (int i = 0; i < inner.size(); ++i) {
    const auto& nb = inner.neighbour[static_cast<size_t>(i)];
    if (nb[0] < 0 || nb[1] < 0 || nb[2] < 0) inner.latex[static_cast<size_t>(i)].area = 0.0;
  }
  inner.invalidate();
  const double r = 0.4, unit = 0.5 * kD / (r * r) * interior_area(s);
  const Bent b = bend(m.x, r);
  EXPECT_NEAR(set_energy(inner, b.cylinder) / unit, 1.0, 0.03);
  EXPECT_NEAR(set_energy(inner, b.sphere) / unit / 3.0, 1.0, 0.03);
  EXPECT_NEAR(set_energy(inner, b.saddle) / unit, 1.0, 0.03);
}

// On a jittered patch (no two neighbours form a parallelogram, so the mean of two planes is not
// exact there), a quadratic graph z = X^T H X / 2 of small slope: every triangle whose own fit
// and whose neighbours' fits count reads II = H (times the normal's tilt, 1 - O(slope^2)) and
// stores the plate's A (D/2)[nu tr(H)^2 + (1 - nu) tr(H^2)] within 0.1 %, through the fits.
TEST(ShellTriangles, OnAJitteredPatchTheFittedGradientsReadAQuadraticExactly) {
  TriPatch m = tri_patch(12, 0.002, 0.3);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  std::vector<bool> rim(static_cast<size_t>(m.x.cols()), false);
  for (int p : m.rim) rim[static_cast<size_t>(p)] = true;
  for (int p = 0; p < m.x.cols(); ++p)
    if (!rim[static_cast<size_t>(p)]) m.x.col(p) += Vec3(0.002 * u(rng), 0.002 * u(rng), 0.0);
  ShellTriangles s;
  s.add_mesh(m.triangles, m.x, kD, 0.5);
  Eigen::Matrix2d h;
  h << 0.5, 0.2, 0.2, -0.3;  // 1/m
  Points x = m.x;
  const Vec2 centre = m.x.rowwise().mean().head<2>();
  for (int p = 0; p < x.cols(); ++p) {
    const Vec2 d = m.x.col(p).head<2>() - centre;
    x(2, p) = 0.5 * d.dot(h * d);
  }
  const double density = 0.5 * kD * (0.5 * h.trace() * h.trace() + 0.5 * (h * h).trace());
  int checked = 0;
  for (int i = 0; i < s.size(); ++i) {
    const auto& n = s.neighbour[static_cast<size_t>(i)];
    if (!s.fit_counts(i) || !s.fit_counts(n[0]) || !s.fit_counts(n[1]) || !s.fit_counts(n[2]))
      continue;
    EXPECT_GT(s.plan(i).coef.rightCols<6>().norm(), 0.0) << "the neighbours' fits are read";
    EXPECT_NEAR(s.energy(i, x) / (s.latex[static_cast<size_t>(i)].area * density), 1.0, 1e-3) << i;
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

// An interior corner of three triangles: two neighbours share their far corner, so the
// triangle's own fit is not posed (five distinct points) and it reads its edges from its
// neighbours' planes. On a sphere it stores a finite, positive energy of the plate's order.
TEST(ShellTriangles, ASingularFitAtACornerOfThreeTrianglesStaysBounded) {
  Points rest(3, 5);  // 0, 1, 2, then Q across edge 1-2 and P around corner 0
  rest << 0, 0.01, 0, 0.01, -0.004, 0, 0, 0.01, 0.01, -0.004, 0, 0, 0, 0, 0;
  ShellTriangles s;
  s.add_mesh({{0, 1, 2}, {2, 1, 3}, {0, 2, 4}, {0, 4, 1}}, rest, kD, 0.5);
  EXPECT_EQ(s.ids(0)[3], 3);
  EXPECT_EQ(s.ids(0)[4], 4);
  EXPECT_EQ(s.ids(0)[5], 4);
  EXPECT_EQ(s.reference[0].quality, 0.0);
  const double r = 0.2;
  Points x = rest;
  for (int p = 0; p < 5; ++p) x(2, p) = (x(0, p) * x(0, p) + x(1, p) * x(1, p)) / (2.0 * r);
  const double e = s.energy(0, x), plate = s.latex[0].area * 0.5 * kD / (r * r) * 3.0;
  EXPECT_TRUE(std::isfinite(e));
  EXPECT_GT(e, 0.1 * plate);
  EXPECT_LT(e, 10.0 * plate);
  Points f = Points::Zero(3, 5);
  s.add_forces(x, nullptr, 0, 1, f);
  EXPECT_TRUE(f.allFinite());
  EXPECT_TRUE(s.hessian(0, x, false).allFinite());
  std::printf("singular fit: sphere energy / plate %.3f\n", e / plate);
}

// Bounded below: every triangle's energy is a positive semi-definite form of its curvature, so
// no configuration, however crumpled, stores less than nothing (the Gaussian-curvature term this
// set replaced could: a resin-weighted cone lowered the energy without bound).
TEST(ShellTriangles, NoConfigurationStoresANegativeEnergy) {
  const TriPatch m = tri_patch(6, 0.002, 0.1);
  ShellTriangles s;
  s.add_mesh(m.triangles, m.x, kD, 0.5);
  for (int i = 0; i < s.size(); i += 3)
    s.resin[static_cast<size_t>(i)] = {s.latex[static_cast<size_t>(i)].metric_inverse,
                                       s.latex[static_cast<size_t>(i)].area, 500.0 * kD, 1.0 / 3.0};
  s.invalidate();  // the members written directly
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    Points x = m.x;
    const double amplitude = 0.0005 * (1 + trial % 5);
    for (int p = 0; p < x.cols(); ++p) x(2, p) += amplitude * g(rng);
    for (int i = 0; i < s.size(); ++i) ASSERT_GE(s.energy(i, x), 0.0) << trial << " " << i;
  }
}

// A triangle, its three neighbours and theirs (ten triangles, jittered), relabelled so that the
// first triangle's stencil is particles 0..11 in slot order.
struct Ring {
  Points x;
  std::vector<std::array<int, 3>> triangles;
};

Ring ring(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto mirror = [](const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 d = (b - a).normalized();
    const Vec3 foot = a + d * d.dot(p - a);
    return Vec3(2.0 * foot - p);
  };
  std::vector<Vec3> p{Vec3(0, 0, 0), Vec3(0.01, 0, 0), Vec3(0.004, 0.009, 0)};
  std::vector<std::array<int, 3>> tris{{0, 1, 2}};
  for (int k = 0; k < 3; ++k) {
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    p.push_back(
        mirror(p[static_cast<size_t>(k)], p[static_cast<size_t>(a)], p[static_cast<size_t>(b)]));
    const int f = static_cast<int>(p.size()) - 1;
    tris.push_back({b, a, f});
    // The neighbour's outer neighbours, across (a, f) and (f, b).
    p.push_back(
        mirror(p[static_cast<size_t>(b)], p[static_cast<size_t>(a)], p[static_cast<size_t>(f)]));
    tris.push_back({a, static_cast<int>(p.size()) - 1, f});
    p.push_back(
        mirror(p[static_cast<size_t>(a)], p[static_cast<size_t>(f)], p[static_cast<size_t>(b)]));
    tris.push_back({f, static_cast<int>(p.size()) - 1, b});
  }
  for (size_t q = 3; q < p.size(); ++q) p[q] += Vec3(0.0015 * u(rng), 0.0015 * u(rng), 0.0);
  Ring out;
  out.x = Points(3, static_cast<Eigen::Index>(p.size()));
  for (size_t q = 0; q < p.size(); ++q) out.x.col(static_cast<Eigen::Index>(q)) = p[q];
  ShellTriangles s;
  s.add_mesh(tris, out.x, kD, 0.5);
  const std::array<int, 12> order = s.ids(0);
  std::vector<int> label(p.size(), -1);
  for (int a = 0; a < 12; ++a) label[static_cast<size_t>(order[static_cast<size_t>(a)])] = a;
  Points relabelled = out.x;
  for (size_t q = 0; q < p.size(); ++q)
    relabelled.col(label[q]) = out.x.col(static_cast<Eigen::Index>(q));
  out.x = relabelled;
  for (auto& t : tris)
    for (int& c : t) c = label[static_cast<size_t>(c)];
  out.triangles = tris;
  return out;
}

// Element 0 of that ring (particles 0..11 in stencil order): forces and Hessian match central
// differences (relative 1e-6) on random, compressed and nearly folded stencils, with the fits of
// all four counted; then with a resin neighbour (a clamped edge), resin on the element and one
// neighbour (two free edges), and resin on an outer triangle (a neighbour's fit not counted).
TEST(ShellTriangles, GradientAndHessianMatchFiniteDifferences) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 7; ++trial) {
    const Ring r = ring(rng);
    ShellTriangles s;
    s.add_mesh(r.triangles, r.x, kD, 0.5);
    std::array<int, 12> slots{};
    for (int a = 0; a < 12; ++a) slots[static_cast<size_t>(a)] = a;
    ASSERT_EQ(s.ids(0), slots);
    const ShellReference ref = s.reference[0];
    EXPECT_GT(ref.quality, 0.0);
    const auto stiff = [&](int i) {
      s.resin[static_cast<size_t>(i)] = {s.latex[static_cast<size_t>(i)].metric_inverse,
                                         s.latex[static_cast<size_t>(i)].area, 300.0 * kD, 0.3};
      s.invalidate();
    };
    if (trial == 4) {
      stiff(s.neighbour[0][1]);
      EXPECT_EQ(s.edges(0)[1], ShellTriangles::Edge::clamped);
    }
    if (trial == 5) {
      stiff(0);
      stiff(s.neighbour[0][2]);
      EXPECT_EQ(s.free_edges(0), (std::array<bool, 3>{true, true, false}));
    }
    if (trial == 6) {
      stiff(s.neighbour[s.neighbour[0][0]][1] == 0 ? s.neighbour[s.neighbour[0][0]][0]
                                                   : s.neighbour[s.neighbour[0][0]][1]);
      EXPECT_FALSE(s.fit_counts(s.neighbour[0][0]));
    } else if (trial < 4) {
      for (int k = 0; k < 3; ++k) EXPECT_TRUE(s.fit_counts(s.neighbour[0][static_cast<size_t>(k)]));
    }
    Points x = r.x;
    const double scale = trial == 2 ? 0.6 : 1.0;  // compressed
    x.row(0) *= scale;
    for (int k = 0; k < 36; ++k) x(k % 3, k / 3) += 0.002 * u(rng);
    if (trial == 3) x(2, 3) += 0.012;  // a neighbour folded far over
    expect_kernel_matches_finite_differences(s, x, "shell triangle");
    // A coat's rest curvature on every triangle, part way through the release (the free
    // edges' slopes then gain an offset).
    for (auto& c : s.coat_curvature) c = 2e-3 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    s.coat_share = 0.7;
    s.invalidate();
    expect_kernel_matches_finite_differences(s, x, "coated shell triangle");
  }
}

// A coat's rest curvature II0 = E^T k0 E (E the triangle's edges): the patch bent to that
// curvature stores almost nothing, rim triangles (free edges) included, against the plate
// energy (D/2) k0 : k0 A it stores flat; bent the other way it stores four times its flat energy.
TEST(ShellTriangles, APatchBentToItsCoatsCurvatureStoresNothing) {
  const double r = 0.4;
  for (double angle : {0.0, 0.5}) {
    const TriPatch m = tri_patch(16, 0.002, angle);
    ShellTriangles s;
    s.add_mesh(m.triangles, m.x, kD, 0.5);
    const Eigen::Matrix2d k0 = Eigen::Vector2d(1.0 / r, 0.0).asDiagonal();  // bent about y
    for (int i = 0; i < s.size(); ++i) {
      const auto& p = s.ids(i);
      Eigen::Matrix2d e;
      e << (m.x.col(p[1]) - m.x.col(p[0])).head<2>(), (m.x.col(p[2]) - m.x.col(p[0])).head<2>();
      const Eigen::Matrix2d ii = e.transpose() * k0 * e;
      s.coat_curvature[static_cast<size_t>(i)] = Eigen::Vector3d(ii(0, 0), ii(0, 1), ii(1, 1));
    }
    s.coat_share = 1.0;
    s.invalidate();
    double area = 0.0;
    for (const PlateLayer& l : s.latex) area += l.area;
    // Flat, the rim triangles store less: their free edges' slopes relax towards II0.
    const double flat = set_energy(s, m.x), plate = 0.5 * kD / (r * r) * area;
    EXPECT_GT(flat / plate, 0.85) << angle;
    EXPECT_LE(flat / plate, 1.0 + 1e-9) << angle;
    const Bent b = bend(m.x, r);
    EXPECT_LT(set_energy(s, b.cylinder) / plate, 1e-3) << angle;
    Points other = b.cylinder;
    other.row(2) *= -1.0;
    EXPECT_NEAR(set_energy(s, other) / flat, 4.0, 0.01) << angle;
  }
}

// Across an edge with resin on one side, the kink goes to the latex. Two triangles folded along
// their shared edge: both latex, each reads half the fold (the mean of the two planes) and stores
// about half the energy. With resin on one (1000 times the latex's plate), its edge against the
// latex is free and the latex's clamped to the resin's plane: the resin stores nothing and the
// latex reads the whole fold, 4 times what it stored before (plates in series: a stiff
// neighbour holds the slope, so the soft one bends alone, as at a clamp).
TEST(ShellTriangles, ResinOnOneSideLeavesTheKinkToTheLatex) {
  Points rest(3, 4);
  rest << 0, 0.01, 0.005, 0.005, 0, 0, 0.008, -0.008, 0, 0, 0, 0;
  const std::vector<std::array<int, 3>> tris{{0, 1, 2}, {1, 0, 3}};
  ShellTriangles s;
  s.add_mesh(tris, rest, kD, 0.5);
  Points folded = rest;
  folded(2, 3) = 0.002;  // the latex side turned about the edge 0-1
  const double latex_only = set_energy(s, folded);
  EXPECT_GT(latex_only, 0.0);
  EXPECT_NEAR(s.energy(0, folded) / latex_only, 0.5, 0.05);  // each about half
  ShellTriangles coated = s;
  coated.resin[0] = {s.latex[0].metric_inverse, s.latex[0].area, 1000.0 * kD, 1.0 / 3.0};
  coated.invalidate();                                           // the copy carries s's plans
  EXPECT_EQ(coated.edges(0)[2], ShellTriangles::Edge::free);     // the resin's edge
  EXPECT_EQ(coated.edges(1)[2], ShellTriangles::Edge::clamped);  // the latex's edge
  EXPECT_NEAR(coated.energy(0, folded), 0.0, 1e-9 * latex_only);
  EXPECT_NEAR(coated.energy(1, folded) / s.energy(1, folded), 4.0, 0.05);
}

}  // namespace
}  // namespace membra
