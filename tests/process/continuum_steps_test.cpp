// Protocol steps on the continuum sheet (docs/model.md, "The continuum shell"): a grow step's
// radial shrink of exp5 ruffles the sheet into a saddle, as on the lattice; what the continuum
// cannot take is refused before anything runs, naming the field.
#include <cstdio>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <stb_image_write.h>
#include <unistd.h>

#include "membra/core/input_error.hpp"
#include "membra/io/scene.hpp"
#include "membra/model/triangle_resin.hpp"
#include "membra/output/report.hpp"
#include "membra/process/path.hpp"
#include "membra/process/run.hpp"

namespace membra {
namespace {

const std::string kExampleDir = std::string(MEMBRA_SOURCE_DIR) + "/examples/";

// exp5 (the periphery shrinks radially by 15 % at each edge's middle, the centre keeps its
// length): the rings are too long for their radius, so the sheet takes negative curvature. On a
// coarse 20 mm mesh, five increments: an anticlastic quadric (k1 > 0 > k2), its radii within a
// factor two of each other (the square's symmetry), and not flat.
TEST(ContinuumSteps, RadialShrinkRufflesIntoASaddle) {
  const Scene scene = load_scene(kExampleDir + "exp5_shrink.json",
                                 {"model=continuum", "sheet.mesh.max_edge=20",
                                  "protocol.0.increments=5", "simulation.max_seconds=300"});
  const RunResult r = run_scene(scene);
  ASSERT_TRUE(r.solve.converged) << r.solve.message;
  const QuadricFit& q = r.shape.quadric;
  ASSERT_TRUE(q.valid);
  EXPECT_EQ(q.classification, "anticlastic") << q.k1 << " " << q.k2;
  EXPECT_GT(q.k1, 0.0);
  EXPECT_LT(q.k2, 0.0);
  EXPECT_LT(q.k1 / -q.k2, 2.0);
  EXPECT_GT(q.k1 / -q.k2, 0.5);
  // report.json says which model ran and the mesh as made and asked for (the contract a script
  // reruns a scene at half the element size with).
  const nlohmann::json j = make_report(scene, r);
  EXPECT_EQ(j["model"], "continuum");
  const nlohmann::json& mesh = j["mesh"];
  EXPECT_EQ(mesh["vertices"], r.prepared.membrane.sheet.model.num_particles());
  EXPECT_GT(mesh["triangles"].get<int>(), mesh["vertices"].get<int>());
  EXPECT_EQ(mesh["max_edge"], 20.0);
  EXPECT_EQ(mesh["elements_across"], 4);
  EXPECT_GT(mesh["min_angle_deg"].get<double>(), 20.0);
  EXPECT_EQ(mesh["laws"]["sheet"], "neo_hookean");
  EXPECT_EQ(mesh["wrinkling"], "full");
}

// bilayer_roll on the continuum (a coarse 20 mm mesh): the coat on top rolls the sheet along x
// into the lattice's arc, 51 mm high (Timoshenko's radius 210 mm over the 300 mm stretched
// length), a cylindrical quadric bulging towards the coat.
TEST(ContinuumSteps, BilayerRollRollsAsOnTheLattice) {
  const RunResult r = run_scene(
      load_scene(kExampleDir + "bilayer_roll.json", {"model=continuum", "sheet.mesh.max_edge=20"}));
  ASSERT_TRUE(r.solve.converged) << r.solve.message;
  std::printf("bilayer_roll on the continuum: %.1f mm high, quadric %s, radius %.0f mm\n",
              r.shape.height * 1e3, r.shape.quadric.classification.c_str(),
              1e3 / r.shape.quadric.k1);
  EXPECT_NEAR(r.shape.height * 1e3, 51.0, 2.5);
  EXPECT_EQ(r.shape.quadric.classification, "cylindrical");
  EXPECT_NEAR(1.0 / r.shape.quadric.k1, 0.197, 0.01);
  // The coat's step says in report.json how many triangles lie across its outline (none: it
  // covers the whole frame; the count itself is tested in PartialCover and on the mask above).
  const nlohmann::json steps =
      make_report(load_scene(kExampleDir + "bilayer_roll.json"), r)["steps"];
  ASSERT_EQ(steps[1]["step"], "impregnate");
  EXPECT_EQ(steps[1]["partly_covered"], 0);
}

TEST(ContinuumSteps, SpringFamiliesAreRefusedByName) {
  try {
    (void)run_scene(load_scene(kExampleDir + "exp5_shrink.json",
                               {"model=continuum", "protocol.0.family=shear"}));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/protocol/0/family"), std::string::npos) << e.what();
  }
  // So are added springs' families: on a mesh they lie along its edges.
  try {
    (void)run_scene(load_scene(
        kExampleDir + "exp5_shrink.json",
        {"model=continuum",
         R"(protocol.0={"step": "add_springs", "along": "shear", "pattern": {"strip": {"points":
         [[0, 20], [100, 20]], "width": 4}}})"}));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/protocol/0/along"), std::string::npos) << e.what();
  }
}

// A 100 mm continuum sheet (max_edge mm) held 1.3 x 1.3 on its frame, with springs at 0.8 of
// their length in a 30 mm circle on the frame.
nlohmann::json springs_scene(double max_edge) {
  return {{"name", "springs"},
          {"model", "continuum"},
          {"sheet", {{"size", {100, 100}}, {"mesh", {{"max_edge", max_edge}}}}},
          {"simulation", {{"solver", "newton"}, {"G", 0}}},
          {"protocol",
           {{{"step", "stretch"}, {"lambda", {1.3, 1.3}}},
            {{"step", "add_springs"},
             {"pattern", {{"circle", {{"center", {65, 65}}, {"radius", 30}}}}},
             {"rest_factor", 0.8},
             {"increments", 2},
             {"perturbation", 0}}}}};
}

// add_springs on the continuum: a spring along every mesh edge in the region, by default of
// (sqrt 3 / 2) E t, a network as stiff in plane as the latex whatever the edges' length. On a
// 100 mm sheet held 1.3 x 1.3 on its frame, springs at 0.8 of their length in a 30 mm circle pull
// it in: the particles inside come to 0.90 of their distance from its centre on a 10 mm mesh and
// a 5 mm mesh alike (within 1 %; measured 0.8979 and 0.8976, docs/deformation.md).
TEST(ContinuumSteps, AddedSpringsPullTheirRegionInAlikeOnAnyMesh) {
  const auto pulled = [](double max_edge) {
    const RunResult r = run_scene(parse_scene(springs_scene(max_edge)));
    EXPECT_TRUE(r.solve.converged) << r.solve.message;
    EXPECT_GT(r.steps.at(1).springs_added, 0);
    // The particles inside the circle on the frame: their mean distance from its centre, now
    // against before (the paper position times the stretch).
    const Points& x = r.prepared.membrane.state.x;
    const Points& paper = r.prepared.membrane.sheet.model.reference;
    const Vec2 centre(0.065, 0.065);
    double now = 0.0, before = 0.0;
    for (int p = 0; p < x.cols(); ++p) {
      const double d0 = (1.3 * paper.col(p).head<2>() - centre).norm();
      if (d0 > 0.025) continue;
      before += d0;
      now += (x.col(p).head<2>() - centre).norm();
    }
    return now / before;
  };
  const double coarse = pulled(10), fine = pulled(5);
  std::printf("added springs pull their region in to %.4f (10 mm mesh), %.4f (5 mm)\n", coarse,
              fine);
  EXPECT_NEAR(coarse / fine, 1.0, 0.01);
  EXPECT_GT(fine, 0.8);
  EXPECT_LT(fine, 0.99);
}

TEST(ContinuumSteps, Exp7sSlitAndHoleAreExactOnTheMesh) {
  const Scene scene = load_scene(kExampleDir + "exp7_cut.json", {"model=continuum"});
  const RunResult r = run_scene(scene);
  ASSERT_TRUE(r.solve.converged) << r.solve.message;
  const Sheet& sheet = r.prepared.membrane.sheet;
  EXPECT_EQ(sheet.mesh.vertices, sheet.model.num_particles());
  ASSERT_EQ(r.concentrations.size(), 2u);
  EXPECT_GT(r.concentrations[0].concentration, 2.0);  // the slit's tips
  const StressConcentration& c = r.concentrations[1];
  ASSERT_TRUE(c.has_edge);
  EXPECT_NEAR(c.hole_radius, std::sqrt(0.010 * 0.015), 2e-5);
  EXPECT_NEAR(std::abs(std::sin(c.edge_angle)), 1.0, 0.02);
  EXPECT_GT(c.edge_concentration, 2.0);
}

// exp7's slit and hole on a table (the sheet held on its frame above it): the sheets the cuts
// rebuild (a hole removes particles, a slit adds its lips) keep one table contact under every
// particle, at its new weight. On a 20 mm mesh (704 vertices, against 1 305 by default, which
// took two minutes under the sanitizers): the bookkeeping does not depend on the mesh.
TEST(ContinuumSteps, ASlitAndAHoleOnATableKeepTheTableUnderEveryParticle) {
  const Scene scene =
      load_scene(kExampleDir + "exp7_cut.json",
                 {"model=continuum", "simulation.support=table", "simulation.G=9.81",
                  "simulation.max_seconds=300", "sheet.mesh.max_edge=20"});
  const RunResult r = run_scene(scene);
  ASSERT_TRUE(r.solve.converged) << r.solve.message;
  const Model& model = r.prepared.membrane.sheet.model;
  ASSERT_EQ(model.table.size(), model.num_particles());
  double weight = 0.0;
  for (int p = 0; p < model.num_particles(); ++p) weight += model.mass[static_cast<size_t>(p)];
  EXPECT_NEAR(r.table.weight, weight * 9.81, 1e-12 * r.table.weight);
  // Still on its frame (exp7 is not released): the frame carries part of the weight.
  EXPECT_GT(r.table.reaction, 0.0);
  EXPECT_LE(r.table.reaction, r.table.weight * (1.0 + 1e-6));
}

// A hole after added springs (on a 100 mm sheet held 1.3 x 1.3, springs at 0.8 of their length
// in a 30 mm circle on the frame, then a 12 mm hole across the circle's edge): the springs are
// carried by their particles, those of the particles the hole took are gone, and the rest still
// pull.
TEST(ContinuumSteps, AHoleAfterAddedSpringsKeepsTheSpringsOutsideIt) {
  nlohmann::json j = springs_scene(10);
  j["protocol"].push_back(
      {{"step", "cut"}, {"hole", {{"circle", {{"center", {90, 90}}, {"radius", 12}}}}}});
  const RunResult r = run_scene(parse_scene(j));
  ASSERT_TRUE(r.solve.converged) << r.solve.message;
  const int added = r.steps.at(1).springs_added;
  const Model& model = r.prepared.membrane.sheet.model;
  EXPECT_GT(added, 0);
  EXPECT_GT(model.added_springs.size(), 0);
  EXPECT_LT(model.added_springs.size(), added);  // the hole took some
  for (int s = 0; s < model.added_springs.size(); ++s) {
    for (int p : model.added_springs.ids(s)) ASSERT_LT(p, model.num_particles());
    // None ties the hole's rim across it: its middle on the frame is outside the hole.
    const auto [a, b] = model.added_springs.ids(s);
    const Vec2 middle = 0.65 * (model.reference.col(a) + model.reference.col(b)).head<2>();
    EXPECT_GT((middle - Vec2(0.090, 0.090)).norm(), 0.012) << s;
  }
  // The carried springs still pull their region in: on the whole shorter than the edges they were
  // laid on (rest length / 0.8), though the hole's opening stretches those beside it.
  const Points& x = r.prepared.membrane.state.x;
  double ratio = 0.0;
  for (int s = 0; s < model.added_springs.size(); ++s) {
    const auto [a, b] = model.added_springs.ids(s);
    ratio += (x.col(a) - x.col(b)).norm() / (model.added_springs.rest_length[s] / 0.8);
  }
  ratio /= model.added_springs.size();
  std::printf("springs after the hole: %d of %d, at %.4f of their laid length on average\n",
              model.added_springs.size(), added, ratio);
  EXPECT_LT(ratio, 0.97);
}

// Slits leaving the sheet and holes reaching the outline: refused before anything runs, naming
// the field (cuts after the release: cut_after_motion_test.cpp).
TEST(ContinuumSteps, CutsTheMeshCannotTakeAreRefusedByName) {
  const auto refused = [](std::vector<std::string> sets, const std::string& field) {
    sets.insert(sets.begin(), "model=continuum");
    try {
      (void)run_scene(load_scene(kExampleDir + "exp7_cut.json", sets));
      ADD_FAILURE() << "no error for " << field;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  refused({"protocol.1.line=[[102, 50], [400, 90]]"}, "/protocol/1/line");
  refused({"protocol.1={\"step\": \"cut\", \"hole\": {\"circle\": {\"center\": [5, 100], "
           "\"radius\": 15}}}"},
          "/protocol/1/hole");
}

// exp5 on a table (docs/model.md, "On a table"), a coarse 20 mm mesh: 0.5 mm latex 200 mm across
// cannot hold its saddle against its weight (gravity bends it over ~17 mm), so it settles low
// on the table, which carries its whole weight; the report says so, and the piece is written as
// it lies (not posed).
TEST(ContinuumSteps, OnATableTheGrownSheetSettlesUnderItsWeight) {
  const Scene scene =
      load_scene(kExampleDir + "exp5_shrink.json",
                 {"model=continuum", "sheet.mesh.max_edge=20", "protocol.0.increments=5",
                  "simulation.max_seconds=300", "simulation.support=table", "simulation.G=9.81"});
  const RunResult r = run_scene(scene);
  ASSERT_TRUE(r.solve.converged) << r.solve.message;
  EXPECT_LT(r.shape.global_height, 0.025);  // floating: a saddle of about 50 mm (above)
  EXPECT_GT(r.table.touching, r.prepared.membrane.sheet.model.num_particles() / 2);
  EXPECT_NEAR(r.table.reaction, r.table.weight, 1e-3 * r.table.weight);
  EXPECT_LT(r.table.max_depth, 20 * TableContact::kDefaultSoftness);
  const nlohmann::json j = make_report(scene, r);
  EXPECT_EQ(j["support"], "table");
  EXPECT_NEAR(j["table"]["weight_N"].get<double>(), r.table.weight, 1e-12);
  EXPECT_FALSE(j["pose"]["posed"].get<bool>());
  EXPECT_GT(j["energy_parts"]["table"].get<double>(), 0.0);
}

// A grey PNG mask on the continuum (docs/model.md, "Meshes that follow the pattern"): a dark disk
// 40 px across with a one-pixel ramp at its rim, off the image's centre, 2.5 mm a pixel on the
// 300 x 200 mm frame. The mesh follows the mask's 0.5 grey level: every vertex between resin and
// latex lies on the disk pulled back by the stretch (an ellipse of semi-axes 33.3 and 50 mm on
// the natural sheet) within 0.15 mm (0.06 px: the ramp read bilinearly, in 8 bits), the resin's
// natural area is the ellipse's within 0.5 % and its centroid where the image puts it (row 0 at
// the top) within 0.1 mm.
TEST(ContinuumSteps, AGreyImageMaskIsMeshedAlongItsOutline) {
  const int w = 120, h = 80;
  const double radius = 20.0, cx = 40.0, cy = 30.0;  // px, from the image's top-left corner
  std::vector<unsigned char> grey(static_cast<size_t>(w) * h);
  for (int row = 0; row < h; ++row)
    for (int col = 0; col < w; ++col) {
      const double d = std::hypot(col + 0.5 - cx, row + 0.5 - cy) - radius;
      grey[static_cast<size_t>(row) * w + col] =
          static_cast<unsigned char>(std::lround(255.0 * std::clamp(0.5 + 0.5 * d, 0.0, 1.0)));
    }
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("membra_mask_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  ASSERT_TRUE(stbi_write_png((dir / "disk.png").c_str(), w, h, 1, grey.data(), w));
  const Scene scene = parse_scene(nlohmann::json::parse(R"({"name": "mask", "model": "continuum",
    "sheet": {"size": [200, 200], "material": "latex", "mesh": {"max_edge": 10}},
    "simulation": {"G": 0},
    "protocol": [{"step": "stretch", "lambda": [1.5, 1.0]},
      {"step": "impregnate", "material": "epoxy",
       "pattern": {"image": {"file": "disk.png", "origin": [0, 0], "size": [300, 200]}}}]})"),
                                  dir);
  std::filesystem::remove_all(dir);  // the scene holds the image it read
  SceneRun run(scene);
  for (const ProtocolStep& step : scene.protocol) ASSERT_TRUE(run.apply(step));
  const Sheet& sheet = run.partial().prepared.membrane.sheet;
  const std::vector<bool> resin = triangle_resin(sheet);
  const Points& x = sheet.model.reference;
  const double a = 0.050 / 1.5, b = 0.050;                         // m, natural sheet
  const Vec3 centre(2.5e-3 * cx / 1.5, 0.200 - 2.5e-3 * cy, 0.0);  // row 0 at the top
  double area = 0.0;
  Vec3 moment = Vec3::Zero();
  std::vector<int> side(static_cast<size_t>(x.cols()), 0);  // bit 1: resin, bit 2: latex
  for (size_t t = 0; t < sheet.triangles.size(); ++t) {
    const Triangle& tri = sheet.triangles[t];
    const double at =
        0.5 * (x.col(tri[1]) - x.col(tri[0])).cross(x.col(tri[2]) - x.col(tri[0])).norm();
    for (const int v : tri) side[static_cast<size_t>(v)] |= resin[t] ? 1 : 2;
    if (!resin[t]) continue;
    area += at;
    moment += at * (x.col(tri[0]) + x.col(tri[1]) + x.col(tri[2])) / 3.0;
  }
  EXPECT_NEAR(area / (std::numbers::pi * a * b), 1.0, 5e-3);
  EXPECT_LT((moment / area - centre).norm(), 1e-4);
  int on_outline = 0;
  for (int v = 0; v < x.cols(); ++v) {
    if (side[static_cast<size_t>(v)] != 3) continue;
    const Vec3 d = x.col(v) - centre;
    const double level = std::hypot(d.x() / a, d.y() / b);  // 1 on the ellipse
    EXPECT_NEAR((level - 1.0) * a, 0.0, 1.5e-4) << "vertex " << v;
    ++on_outline;
  }
  EXPECT_GT(on_outline, 100);  // the ellipse's 260 mm of outline on a mesh that follows it
  ASSERT_EQ(run.partial().steps.size(), 2u);
  EXPECT_EQ(run.partial().steps[1].partly_covered, 0);
}

}  // namespace
}  // namespace membra
