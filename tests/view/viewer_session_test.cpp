// The viewer's session without a window: the protocol buttons, painting, cuts, holes, pins,
// live parameters, undo/redo, and that a saved session is a scene `membra run` reproduces.
#include <gtest/gtest.h>

#include <algorithm>

#include <Eigen/SVD>

#include "membra/core/units.hpp"
#include "membra/io/scene.hpp"
#include "membra/io/scene_writer.hpp"
#include "membra/process/run.hpp"
#include "membra/view/color_field.hpp"
#include "membra/view/viewer_session.hpp"
#include "view/rolling_strip.hpp"

namespace membra {
namespace {
using nlohmann::json;

// 100 x 100 mm latex on 13 x 13 particles, weightless; stretched 1.5 along x, held left/right.
Scene small_scene(json protocol = json::array()) {
  return parse_scene({{"name", "small"},
                      {"sheet", {{"size", {100, 100}}, {"resolution", {13, 13}}}},
                      {"simulation", {{"G", 0.0}}},
                      {"protocol", protocol}});
}

// A protocol as the scene writer writes it (every default spelled out), for comparisons.
json written_protocol(const json& protocol) {
  return write_scene(small_scene(protocol))["protocol"];
}

Vec2 mm(double x, double y) {
  return Vec2(x, y) * units::mm;
}

int resin_springs(const ViewerSession& s) {
  const auto& f = s.membrane().sheet.model.springs.resin_fraction;
  return static_cast<int>(std::count_if(f.begin(), f.end(), [](double r) { return r > 0.0; }));
}

TEST(ViewerSession, TheProtocolButtonsGoInOrder) {
  ViewerSession s(small_scene());
  EXPECT_EQ(s.stage(), Stage::flat);
  EXPECT_NE(s.impregnate(), "");  // nothing stretched yet
  EXPECT_NE(s.release(), "");
  EXPECT_NE(s.paint(mm(50, 50), 5 * units::mm), "");  // paint goes on the stretched sheet
  ASSERT_EQ(s.stretch(), "");
  EXPECT_EQ(s.stage(), Stage::stretched);
  EXPECT_NE(s.stretch(), "");  // once
  // The frame is 1.5 x 100 mm wide now.
  const Points& x = s.membrane().state.x;
  EXPECT_NEAR(x.row(0).maxCoeff(), 0.150, 1e-12);
  EXPECT_NE(s.impregnate(), "");  // no resin painted
  ASSERT_EQ(s.paint(mm(75, 50), 15 * units::mm), "");
  ASSERT_EQ(s.impregnate(), "");
  EXPECT_EQ(s.stage(), Stage::impregnated);
  EXPECT_GT(resin_springs(s), 10);
  EXPECT_NE(s.paint(mm(20, 20), 5 * units::mm), "");  // after impregnation: refused
  ASSERT_EQ(s.release(), "");
  EXPECT_EQ(s.stage(), Stage::released);
  EXPECT_EQ(s.log().size(), 3u);
}

TEST(ViewerSession, PaintedResinLiesUnderTheBrushAndEraseRemovesIt) {
  ViewerSession s(small_scene());
  ASSERT_EQ(s.stretch(), "");
  ASSERT_EQ(s.paint(mm(75, 50), 20 * units::mm), "");
  ASSERT_EQ(s.paint(mm(75, 50), 10 * units::mm, true), "");  // a ring is left
  const PatternPtr p = s.resin_pattern();
  ASSERT_TRUE(p);
  EXPECT_TRUE(p->contains(mm(75 + 15, 50)));
  EXPECT_FALSE(p->contains(mm(75, 50)));
  EXPECT_FALSE(p->contains(mm(75 + 25, 50)));
  // The pattern colour shows it before impregnation: 1 on the ring, 0 in the hole.
  const ColorField f = color_field(s, ColorMode::pattern);
  const int centre = s.nearest_particle(mm(75, 50));
  const int ring = s.nearest_particle(mm(75 + 12.5, 50));
  EXPECT_EQ(f.values[static_cast<size_t>(centre)], 0.0);
  EXPECT_EQ(f.values[static_cast<size_t>(ring)], 1.0);
  // The same pattern written into a scene file reads back as the same region.
  json scene = s.to_scene_json();
  ASSERT_TRUE(s.resin_pattern_spec().has_value());
  scene["protocol"].push_back(
      {{"step", "impregnate"}, {"pattern", write_pattern(*s.resin_pattern_spec())}});
  const PatternPtr again = scene_pattern(parse_scene(scene));
  for (const Vec2& q : {mm(90, 50), mm(75, 50), mm(100, 50), mm(75, 62)})
    EXPECT_EQ(again->contains(q), p->contains(q)) << q.transpose();
}

// On the continuum (no springs) the pattern colour reads the impregnated triangles: all resin at
// the painted disc's centre, none far from it.
TEST(ViewerSession, TheContinuumsPatternColourShowsItsResinTriangles) {
  Scene scene = small_scene();
  scene.model = SheetModel::continuum;
  ViewerSession s(scene);
  ASSERT_EQ(s.stretch(), "");
  ASSERT_EQ(s.paint(mm(75, 50), 20 * units::mm), "");
  ASSERT_EQ(s.impregnate(), "");
  ASSERT_FALSE(s.resin_pattern());  // applied: nothing pending shows in the colour
  const ColorField f = color_field(s, ColorMode::pattern);
  EXPECT_EQ(f.values[static_cast<size_t>(s.nearest_particle(mm(75, 50)))], 1.0);
  EXPECT_EQ(f.values[static_cast<size_t>(s.nearest_particle(mm(140, 90)))], 0.0);
  const auto resin = std::count(f.values.begin(), f.values.end(), 1.0);
  EXPECT_GT(resin, 10);
}

// The live relaxation (FIRE) does not hold self-contact: the viewer says so, and the session it
// saves leaves it off, as the path it took had none (docs/viewer.md, "Limits").
TEST(ViewerSession, SaysItsLiveRelaxationHasNoSelfContactAndSavesWithoutIt) {
  Scene scene = small_scene();
  scene.model = SheetModel::continuum;
  scene.simulation.solver = Solver::newton;
  scene.simulation.self_contact.on = true;
  const ViewerSession s(scene);
  EXPECT_NE(s.grid_warning().find("self-contact"), std::string::npos);
  EXPECT_FALSE(s.to_scene().simulation.self_contact.on);
  EXPECT_FALSE(write_scene(s.to_scene())["simulation"].contains("self_contact"));
}

// A strip coated on one face rolls past a full turn; the live relaxation has no self-contact, so
// it settles through itself. The session says where, as `membra run` would, and forgets it when
// the sheet changes (docs/viewer.md, "Display").
TEST(ViewerSession, ASettledFormThatPassesThroughItselfSaysWhere) {
  ViewerSession s(parse_scene(json::parse(kRollingStrip)));
  s.play_scene_protocol();
  ASSERT_TRUE(s.settle().settled);
  const SelfIntersection measured =
      self_intersections(s.membrane().state.x, s.membrane().sheet.triangles);
  EXPECT_GT(measured.pairs, 10);
  EXPECT_EQ(s.crossings().pairs, measured.pairs);
  EXPECT_EQ(s.crossings().triangles, measured.triangles);
  // Stiffer springs: the sheet moves again, and nothing is claimed until it has settled.
  LiveParameters p = s.parameters();
  p.K *= 1.5;
  ASSERT_EQ(s.set_parameters(p), "");
  s.advance(1);
  ASSERT_FALSE(s.settled());
  EXPECT_EQ(s.crossings().pairs, 0);
  ASSERT_TRUE(s.settle().settled);
  EXPECT_EQ(s.crossings().pairs,
            self_intersections(s.membrane().state.x, s.membrane().sheet.triangles).pairs);
  s.reset();
  EXPECT_EQ(s.crossings().pairs, 0);
  EXPECT_TRUE(s.crossings().triangles.empty());
}

TEST(ViewerSession, UndoAndRedoRestoreTheMembraneExactly) {
  ViewerSession s(small_scene());
  ASSERT_EQ(s.stretch(), "");
  const Points stretched = s.membrane().state.x;
  s.begin_edit();  // one brush drag of three dabs
  for (double x : {60.0, 75.0, 90.0}) ASSERT_EQ(s.paint(mm(x, 50), 8 * units::mm), "");
  s.end_edit();
  ASSERT_EQ(s.impregnate(), "");
  ASSERT_EQ(s.release(), "");
  s.settle();
  const Points released = s.membrane().state.x;
  EXPECT_GT((released - stretched).norm(), 1e-3);

  ASSERT_TRUE(s.undo());  // release
  EXPECT_EQ(s.stage(), Stage::impregnated);
  EXPECT_EQ(s.membrane().state.x, stretched);
  ASSERT_TRUE(s.undo());  // impregnate
  EXPECT_EQ(resin_springs(s), 0);
  EXPECT_EQ(s.strokes().size(), 3u);
  ASSERT_TRUE(s.undo());  // the whole drag at once
  EXPECT_TRUE(s.strokes().empty());
  ASSERT_TRUE(s.redo());
  ASSERT_TRUE(s.redo());
  ASSERT_TRUE(s.redo());
  EXPECT_EQ(s.stage(), Stage::released);
  EXPECT_EQ(s.membrane().state.x, released);
  EXPECT_FALSE(s.redo());
}

TEST(ViewerSession, ASavedSessionIsASceneThatRunReproduces) {
  ViewerSession s(small_scene());
  ASSERT_EQ(s.stretch(), "");
  ASSERT_EQ(s.paint(mm(75, 50), 18 * units::mm), "");
  ASSERT_EQ(s.impregnate(), "");
  ASSERT_EQ(s.release(), "");
  const SliceReport r = s.settle();
  ASSERT_TRUE(r.settled) << r.message;
  const Scene saved = parse_scene(s.to_scene_json());
  const RunResult run = run_scene(saved);
  ASSERT_TRUE(run.solve.converged);
  // Same path, same solver: the same form up to the solver's tolerance (the viewer checks
  // convergence at slice ends as well, so it may stop a few iterations apart).
  // The viewer shows the membrane where it was simulated; a run's result is in the reading pose.
  const Points a = (run.pose.rotation * s.membrane().state.x).colwise() + run.pose.translation;
  const Points& b = run.prepared.membrane.state.x;
  ASSERT_EQ(a.cols(), b.cols());
  const double size = 0.1;
  EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-4 * size);
  EXPECT_GT(a.row(2).maxCoeff() - a.row(2).minCoeff(), 1e-3 * size);  // it did bow
}

TEST(ViewerSession, ASavedSceneKeepsItsRampWhenTShrinks) {
  // rk4 with a 0.5 s ramp in 1 s of run: halving T in the viewer would leave 0.5 s of run, and
  // a ramp longer than the run is refused when the saved scene is read.
  Scene scene = parse_scene(
      {{"name", "r"},
       {"sheet", {{"size", {100, 100}}, {"resolution", {5, 5}}}},
       {"simulation",
        {{"solver", "rk4"}, {"G", 0.0}, {"T", 1e-4}, {"steps", 10000}, {"ramp_seconds", 0.5}}},
       {"protocol", json::array()}});
  ViewerSession s(scene);
  LiveParameters p = s.parameters();
  p.T = 2e-5;
  ASSERT_EQ(s.set_parameters(p), "");
  const Scene saved = parse_scene(s.to_scene_json());
  EXPECT_DOUBLE_EQ(saved.simulation.ramp_seconds, 0.5);
  EXPECT_DOUBLE_EQ(saved.simulation.dt, 2e-5);
  EXPECT_GE(static_cast<double>(saved.simulation.steps) * saved.simulation.dt, 0.5 - 1e-12);
}

// On the continuum model cuts belong in the scene (the mesh is made with them): the viewer's
// cut and hole tools say so and leave the sheet as it was.
TEST(ViewerSession, TheContinuumsCutsAreTheScenes) {
  Scene scene = small_scene();
  scene.model = SheetModel::continuum;
  ViewerSession s(scene);
  ASSERT_EQ(s.stretch(), "");
  const int particles = s.membrane().sheet.model.num_particles();
  EXPECT_NE(s.cut(mm(75, 20), mm(75, 80)).find("protocol"), std::string::npos);
  EXPECT_NE(s.hole(mm(110, 50), 12 * units::mm).find("protocol"), std::string::npos);
  EXPECT_EQ(s.membrane().sheet.model.num_particles(), particles);
}

TEST(ViewerSession, CutsHolesAndPinsChangeTheSheetAndUndo) {
  ViewerSession s(small_scene());
  ASSERT_EQ(s.stretch(), "");
  const int springs = s.membrane().sheet.model.springs.size();
  ASSERT_EQ(s.cut(mm(75, 20), mm(75, 80)), "");
  EXPECT_LT(s.membrane().sheet.model.springs.size(), springs);
  EXPECT_NE(s.cut(mm(400, 400), mm(500, 500)), "");  // outside: refused, nothing logged
  const int particles = s.membrane().sheet.model.num_particles();
  ASSERT_EQ(s.hole(mm(110, 50), 12 * units::mm), "");
  EXPECT_LT(s.membrane().sheet.model.num_particles(), particles);
  ASSERT_TRUE(s.undo());
  EXPECT_EQ(s.membrane().sheet.model.num_particles(), particles);

  const int p = s.nearest_particle(mm(75, 50));
  ASSERT_EQ(s.toggle_pin(mm(75, 50)), "");
  EXPECT_TRUE(s.membrane().sheet.model.pinned(p));
  ASSERT_EQ(s.toggle_pin(mm(75, 50)), "");
  EXPECT_FALSE(s.membrane().sheet.model.pinned(p));
  EXPECT_NE(s.toggle_pin(Vec2(0, 50 * units::mm)), "");  // held by the frame
  // The log keeps the cut, not the pin that was taken back.
  ASSERT_EQ(s.log().size(), 2u);
  EXPECT_EQ(s.log()[1].kind(), ProtocolStep::Kind::cut);
}

TEST(ViewerSession, LiveParametersChangeTheModel) {
  ViewerSession s(small_scene());
  LiveParameters p = s.parameters();
  EXPECT_NEAR(p.K, 0.75 * 1.5e6 * 0.5e-3, 1e-9);  // 3/4 E t of latex
  const double k0 = s.membrane().sheet.model.springs.stiffness[0];
  p.K *= 2.0;
  p.G = 3.0;
  p.D = 7.0;
  ASSERT_EQ(s.set_parameters(p), "");
  EXPECT_NEAR(s.membrane().sheet.model.springs.stiffness[0], 2.0 * k0, 1e-12 * k0);
  EXPECT_EQ(s.membrane().sheet.model.gravity.z(), -3.0);
  EXPECT_EQ(s.membrane().sheet.model.velocity_damping, 7.0);
  EXPECT_NEAR(s.to_scene_json()["simulation"]["K"].get<double>(), p.K / 1e3, 1e-12);
  LiveParameters bad = p;
  bad.K = -1.0;
  EXPECT_NE(s.set_parameters(bad), "");
  bad = p;
  bad.lambda.x() = 0.0;
  EXPECT_NE(s.set_parameters(bad), "");
  EXPECT_EQ(s.parameters().K, p.K);  // refused changes leave everything as it was
}

// On a table, G weighs the piece onto it: a new G re-weighs every particle, and a G that would
// lift the piece off is refused (the saved scene would be refused too).
TEST(ViewerSession, OnATableGravityStaysAboveZeroAndWeighsTheContacts) {
  Scene scene = small_scene();
  scene.simulation.support = Support::table;
  scene.simulation.gravity = 9.81;
  ViewerSession s(scene);
  const TableContact& table = s.membrane().sheet.model.table;
  ASSERT_EQ(table.size(), s.membrane().sheet.model.num_particles());
  const double w0 = table.weight[0];
  LiveParameters p = s.parameters();
  p.G = 2.0 * 9.81;
  ASSERT_EQ(s.set_parameters(p), "");
  EXPECT_NEAR(s.membrane().sheet.model.table.weight[0], 2.0 * w0, 1e-12 * w0);
  p.G = 0.0;
  EXPECT_NE(s.set_parameters(p), "");
  EXPECT_EQ(s.parameters().G, 2.0 * 9.81);
  EXPECT_EQ(s.to_scene_json()["simulation"]["support"], "table");
}

TEST(ViewerSession, ADivergingStepIsUndoneNotShown) {
  ViewerSession s(small_scene());
  ASSERT_EQ(s.stretch(), "");
  s.set_mode(LiveMode::dynamics);
  LiveParameters p = s.parameters();
  p.T = 1e-2;  // far beyond RK4's stability limit for this grid
  ASSERT_EQ(s.set_parameters(p), "");
  ASSERT_EQ(s.paint(mm(75, 50), 20 * units::mm), "");
  ASSERT_EQ(s.impregnate(), "");
  ASSERT_EQ(s.release(), "");
  const Points before = s.membrane().state.x;
  SliceReport r;
  for (int i = 0; i < 20 && !r.diverged; ++i) r = s.advance(200);
  ASSERT_TRUE(r.diverged);
  EXPECT_NE(r.message.find("smaller T"), std::string::npos) << r.message;
  EXPECT_TRUE(s.membrane().state.x.allFinite());
}

TEST(ViewerSession, PlaysTheScenesOwnProtocol) {
  const json protocol = {
      {{"step", "stretch"}, {"lambda", {1.5, 1.0}}, {"hold", {"left", "right"}}},
      {{"step", "impregnate"},
       {"pattern", {{"strip", {{"points", {{30, 50}, {120, 50}}}, {"width", 12}}}}}},
      {{"step", "release"}, {"increments", 4}}};
  ViewerSession s(small_scene(protocol));
  EXPECT_EQ(s.parameters().lambda, Vec2(1.5, 1.0));
  s.play_scene_protocol();
  const SliceReport r = s.settle();
  ASSERT_TRUE(r.settled) << r.message;
  EXPECT_EQ(s.stage(), Stage::released);
  EXPECT_GT(resin_springs(s), 5);
  // The log is the scene's protocol, so saving and running gives the same result.
  EXPECT_EQ(s.to_scene_json()["protocol"], written_protocol(protocol));
}

// The steps the viewer once skipped (grow, add_springs, curvature_map) play through the same
// process steps as `membra run`, and the saved session runs to the same form.
// Largest distance between corresponding points after the best rigid motion (Kabsch).
double rigid_distance(const Points& a, const Points& b) {
  const Vec3 ca = a.rowwise().mean(), cb = b.rowwise().mean();
  const Points p = a.colwise() - ca, q = b.colwise() - cb;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(q * p.transpose(),
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1.0 : 1.0;
  const Eigen::Matrix3d r = svd.matrixV() * d * svd.matrixU().transpose();
  return (p - r * q).cwiseAbs().maxCoeff();
}

class ViewerPlaysEveryStep : public ::testing::TestWithParam<json> {};

TEST_P(ViewerPlaysEveryStep, AndTheSavedSessionRunsToTheSameForm) {
  const json protocol = json::array({GetParam()});
  ViewerSession s(small_scene(protocol));
  s.play_scene_protocol();
  const SliceReport r = s.settle();
  ASSERT_TRUE(r.settled) << r.message;
  EXPECT_EQ(s.to_scene_json()["protocol"], written_protocol(protocol));
  const RunResult run = run_scene(parse_scene(s.to_scene_json()));
  ASSERT_TRUE(run.solve.converged) << run.solve.message;
  const Points& a = s.membrane().state.x;
  const Points& b = run.prepared.membrane.state.x;
  ASSERT_EQ(a.cols(), b.cols());
  const double size = 0.1;
  // The step changed the sheet (out of plane, or in plane for the added springs' pull) ...
  EXPECT_GT((a - run.prepared.membrane.sheet.model.reference).cwiseAbs().maxCoeff(), 1e-3 * size);
  // ... and both front ends end in the same form, up to the solver's tolerance (the viewer
  // checks convergence at slice ends as well) and a rigid motion of the free sheet.
  EXPECT_LT(rigid_distance(a, b), 1e-4 * size);
}

INSTANTIATE_TEST_SUITE_P(
    Steps, ViewerPlaysEveryStep,
    ::testing::Values(json{{"step", "grow"},
                           {"factor", "1 + 0.3*sin(pi*(x - w/2)/(2*w))^2"},
                           {"direction", "y"},
                           {"increments", 4}},
                      json{{"step", "add_springs"},
                           {"pattern", {{"circle", {{"center", {50, 50}}, {"radius", 25}}}}},
                           {"rest_factor", 0.8},
                           {"increments", 4}},
                      json{{"step", "curvature_map"}, {"K", 2e-4}, {"increments", 4}}));

// Painted resin takes the face and the bilayer of the scene's impregnate step, and the saved
// protocol keeps them, so `membra run` curls the sheet the same way.
TEST(ViewerSession, PaintedResinFollowsTheScenesBilayer) {
  const json protocol = {
      {{"step", "stretch"}, {"lambda", {1.5, 1.0}}},
      {{"step", "impregnate"},
       {"resin_side", "bottom"},
       {"bilayer", true},
       {"pattern", {{"strip", {{"points", {{0, 50}, {150, 50}}}, {"width", 20}}}}}}};
  ViewerSession s(small_scene(protocol));
  ASSERT_EQ(s.stretch(), "");
  ASSERT_EQ(s.paint(mm(75, 50), 15 * units::mm), "");
  ASSERT_EQ(s.impregnate(), "");
  EXPECT_GT(s.membrane().sheet.model.hinges.size(), 0);
  EXPECT_EQ(s.membrane().resin_side, -1);
  const ImpregnateStep* step = s.log().back().as<ImpregnateStep>();
  ASSERT_TRUE(step);
  EXPECT_TRUE(step->bilayer);
  EXPECT_EQ(step->resin_side, -1);
  const json written = s.to_scene_json()["protocol"].back();
  EXPECT_EQ(written["bilayer"], true);
  EXPECT_EQ(written["resin_side"], "bottom");
}

}  // namespace
}  // namespace membra
