#include "membra/model/continuum_sheet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "membra/model/forces.hpp"
#include "membra/model/membrane.hpp"
#include "membra/model/sheet.hpp"

namespace membra {
namespace {

// A 100 x 80 mm sheet with a resin-like square outline inside: an irregular, graded mesh.
ContinuumSpec spec() {
  ContinuumSpec s;
  s.width = 0.1, s.height = 0.08;
  s.features = {{{0.03, 0.02}, {0.05, 0.025}, {0.045, 0.05}, {0.028, 0.04}}};
  s.mesh.max_edge = 0.01;
  return s;
}

TEST(ContinuumSheet, TheMeshFollowsTheFeaturesAndReportsItself) {
  const Sheet sheet = build_continuum_sheet(spec());
  ASSERT_TRUE(sheet.continuum());
  const SheetMesh& m = sheet.mesh;
  EXPECT_EQ(m.vertices, sheet.model.num_particles());
  EXPECT_EQ(m.triangles, sheet.model.membrane_triangles.size());
  EXPECT_GE(m.min_angle_deg, 25.0 - 1e-9);
  EXPECT_EQ(m.spec.max_edge, 0.01);
  EXPECT_GT(m.narrowest.width, 0.0);
  // Mass: area x thickness x density, the whole sheet's.
  double mass = 0.0;
  for (double v : sheet.model.mass) mass += v;
  EXPECT_NEAR(mass, 0.1 * 0.08 * sheet.material.thickness * sheet.material.density, 1e-15);
  EXPECT_EQ(sheet.model.shell_triangles.size(), m.triangles);  // a plate on every triangle
  EXPECT_DOUBLE_EQ(sheet.grid.width(), 0.1);
}

// Newton's saddle escape: the sheet's larger side on the continuum (its graded edges say nothing
// of the buckling scale), the springs' mean length on the lattice (its springs are 10 mm and
// 10 sqrt 2 mm here, straight and diagonal).
TEST(ContinuumSheet, TheSaddleEscapeIsTheSheetsSizeOnTheLatticeASpring) {
  EXPECT_NEAR(saddle_escape_length(build_continuum_sheet(spec()).model), 0.1, 1e-12);
  const Model lattice = build_sheet({0.1, 0.1, 11, 11}, SheetOptions{}).model;
  EXPECT_GT(saddle_escape_length(lattice), 0.01);
  EXPECT_LT(saddle_escape_length(lattice), 0.01 * std::sqrt(2.0));
}

TEST(ContinuumSheet, TheRimIsTheOutlineWithOutwardNormals) {
  const Sheet sheet = build_continuum_sheet(spec());
  const SheetMesh& m = sheet.mesh;
  ASSERT_FALSE(m.rim.empty());
  for (size_t k = 0; k < m.rim.size(); ++k) {
    const Vec2 p = sheet.model.reference.col(m.rim[k]).head<2>();
    const bool on_edge =
        p.x() < 1e-12 || p.x() > 0.1 - 1e-12 || p.y() < 1e-12 || p.y() > 0.08 - 1e-12;
    EXPECT_TRUE(on_edge) << p.transpose();
    EXPECT_GT(m.rim_normal[k].dot(p - Vec2(0.05, 0.04)), 0.0);  // pointing outwards
  }
}

// The patch test: a uniform deformation of the irregular mesh is an equilibrium (every interior
// particle's force vanishes) with the same stress in every triangle.
TEST(ContinuumSheet, PatchTestUniformStretchGivesUniformStress) {
  Sheet sheet = build_continuum_sheet(spec());
  Eigen::Matrix3d f;
  f << 1.4, 0.1, 0.0, -0.05, 0.9, 0.0, 0.2, 0.1, 1.0;  // stretch, shear and a tilt
  const Points x = f * sheet.model.reference;
  const MembraneTriangles& mt = sheet.model.membrane_triangles;
  const double s0 = mt.stress(0, x, sheet.material.thickness).stress;
  for (int i = 1; i < mt.size(); ++i)
    EXPECT_NEAR(mt.stress(i, x, sheet.material.thickness).stress, s0, 1e-10 * std::abs(s0));
  Points forces = Points::Zero(3, x.cols());
  mt.add_forces(x, nullptr, 0, mt.size(), forces);
  std::vector<bool> rim(static_cast<size_t>(x.cols()), false);
  for (int p : sheet.mesh.rim) rim[static_cast<size_t>(p)] = true;
  double scale = 0.0;
  for (int p = 0; p < x.cols(); ++p) scale = std::max(scale, forces.col(p).norm());
  for (int p = 0; p < x.cols(); ++p) {
    if (rim[static_cast<size_t>(p)]) continue;
    EXPECT_LT(forces.col(p).norm(), 1e-10 * scale) << p;
  }
}

TEST(ContinuumSheet, TheFrameHoldsTheRimTheStretchAsks) {
  Membrane m = make_membrane(build_continuum_sheet(spec()));
  const int all = stretch_frame(m, 1.5, 1.0);
  EXPECT_EQ(all, static_cast<int>(m.sheet.mesh.rim.size()));
  Membrane u = make_membrane(build_continuum_sheet(spec()));
  const int sides = stretch_frame(u, 1.5, 1.0, {true, true, false, false});
  EXPECT_LT(sides, all);
  for (int p : u.frame) {
    const double x = u.sheet.model.reference(0, p);
    EXPECT_TRUE(x < 1e-12 || x > 0.1 - 1e-12);
  }
}

TEST(ContinuumSheet, BadSettingsNameTheMeshField) {
  ContinuumSpec s = spec();
  s.mesh.max_edge = -1.0;
  try {
    build_continuum_sheet(s);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("sheet.mesh.max_edge"), std::string::npos);
  }
  s = spec();
  // A gap of 2 micrometres between two pieces: narrower than the mesher resolves.
  s.features = {{{0.02, 0.02}, {0.04, 0.02}, {0.04, 0.04}, {0.02, 0.04}},
                {{0.040002, 0.02}, {0.06, 0.02}, {0.06, 0.04}, {0.040002, 0.04}}};
  try {
    build_continuum_sheet(s);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("narrower than the mesher resolves"), std::string::npos);
  }
}

TEST(ContinuumSheet, ADiskIsMeshedInsideItsEllipse) {
  ContinuumSpec s = spec();
  s.disk = true;
  s.features.clear();
  const Sheet sheet = build_continuum_sheet(s);
  double area = 0.0;
  for (const Triangle& t : sheet.triangles) {
    const Vec3 a = sheet.model.reference.col(t[0]), b = sheet.model.reference.col(t[1]),
               c = sheet.model.reference.col(t[2]);
    area += 0.5 * (b - a).cross(c - a).z();
  }
  EXPECT_NEAR(area, std::numbers::pi * 0.05 * 0.04, std::numbers::pi * 0.05 * 0.04 * 1e-3);
}

// "wrinkling": "relaxed" relaxes every bare latex triangle; impregnation bonds the latex under
// the resin to it, so those triangles take compression again (membrane_law.hpp).
TEST(ContinuumSheet, RelaxedLatexStaysRelaxedOnlyWhereBare) {
  ContinuumSpec s = spec();
  s.material.wrinkling = Wrinkling::relaxed;
  Membrane m = make_membrane(build_continuum_sheet(s));
  const MembraneTriangles& t = m.sheet.model.membrane_triangles;
  for (const LayerRest& l : t.latex) EXPECT_TRUE(l.law.relaxed);
  impregnate(m, make_polygon(s.features[0]), epoxy(), +1, false);
  int bonded = 0;
  for (int i = 0; i < t.size(); ++i) {
    const auto k = static_cast<size_t>(i);
    EXPECT_EQ(t.latex[k].law.relaxed, !(t.resin[k].volume > 0.0)) << i;
    bonded += t.resin[k].volume > 0.0 ? 1 : 0;
  }
  EXPECT_GT(bonded, 0);
  EXPECT_LT(bonded, t.size());
}

}  // namespace
}  // namespace membra
