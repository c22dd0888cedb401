// Inverse design on small grids: the error falls over the iterations for each kind of target,
// the stencil's scene reproduces the reported form, and an unreachable target says why.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "membra/core/input_error.hpp"
#include "membra/design/stencil_trial.hpp"
#include "membra/io/design_reader.hpp"
#include "membra/io/obj.hpp"
#include "membra/io/scene.hpp"

namespace membra {
namespace {
using nlohmann::json;

// 200 mm frame, 1.5 x 1.5 pre-stretch, an 11 x 11 sheet, 25 mm cells: seconds per design.
json small_design(const json& target, int evaluations = 6) {
  return {{"name", "small"},
          {"target", target},
          {"frame", {{"size", 200}, {"lambda", {1.5, 1.5}}}},
          {"sheet", {{"resolution", 11}}},
          {"resin", {{"min_feature", 4}, {"cell", 25}}},
          {"design", {{"evaluations", evaluations}, {"budget", 600}, {"solver", "newton"}}}};
}

// A small design by the adjoint with `trials` stencil trials and `pieces` piece evaluations.
json small_adjoint_design(const json& target, int trials, int pieces) {
  json design = small_design(target, 4);
  design["design"].update({{"method", "adjoint"},
                           {"density_cell", 25},
                           {"stencil_trials", trials},
                           {"piece_evaluations", pieces}});
  return design;
}

// The scene a design writes, read back as `membra run` would read it, releases into the form the
// design reports (to 1e-6 of the 0.2 m frame).
void expect_scene_reproduces_form(const DesignResult& d) {
  const RunResult again = run_scene(parse_scene(design_scene(d.spec, d.stencil)));
  const Points& a = d.run.prepared.membrane.state.x;
  const Points& b = again.prepared.membrane.state.x;
  ASSERT_EQ(a.cols(), b.cols());
  EXPECT_LE((a - b).cwiseAbs().maxCoeff(), 1e-6 * 0.2);
}

// The goal: at most 2 % of the target's diameter and at most half a flat sheet's error.
void expect_meets_goal(const DesignResult& d) {
  EXPECT_LT(d.rms_error, 2.0);
  EXPECT_LT(d.rms_error, 0.5 * d.flat_error);
}

// Each kind of target with its resin options (a coat on one face for the cap).
class DesignKinds : public ::testing::TestWithParam<std::pair<json, json>> {};

TEST_P(DesignKinds, TheErrorFallsOverTheIterations) {
  json design = small_design(GetParam().first, 12);
  design["resin"].update(GetParam().second);
  const DesignResult d = run_design(parse_design(design));
  ASSERT_GE(d.history.size(), 2u);
  ASSERT_TRUE(d.reachable) << d.message;
  // The search keeps the best; it must have found a better stencil than the start.
  EXPECT_LT(d.rms_error, d.history.front().rms_error - 0.01) << "no improvement on the start";
  // The best is the best equilibrium: unconverged states are recorded but not chosen.
  double best = std::numeric_limits<double>::infinity();
  for (const DesignIteration& it : d.history)
    if (it.note.empty()) best = std::min(best, it.rms_error);
  EXPECT_EQ(d.rms_error, best);
  EXPECT_GT(d.max_error, d.rms_error);
  EXPECT_GT(d.flat_error, 0.0);
}

// 12 stencils each. (The cap had the coat on one face here while a coat's edge creased, which
// made its start 13.8 % and gave the search room; with the coat's edges mended, a coat adds
// little on this grid, and the cap's search improves on its start without one: 5.00 -> 4.90 %.)
INSTANTIATE_TEST_SUITE_P(
    Targets, DesignKinds,
    ::testing::Values(std::pair{json{{"cap", {{"diameter", 160}, {"height", 24}}}}, json::object()},
                      std::pair{json{{"saddle", {{"size", 150}, {"height", 15}}}}, json::object()},
                      std::pair{json{{"cylinder", {{"size", 150}, {"height", 20}}}},
                                json::object()}),
    [](const auto& param_info) { return param_info.param.first.begin().key(); });

// The adjoint method on the three targets, 11 x 11 sheet, 25 mm density cells (8 x 8) — the cap
// 130 mm across: the particles of so coarse a disk span less than its 200 mm, and a 160 mm cap
// asks every cell for more than resin gives (stage 1 says so, and nothing moves) — : the
// objective falls from the metric start, each iterate is a stable equilibrium, and the last
// entry is the stencil laid out from the best densities, simulated and compared as the pattern
// search compares its stencils.
class AdjointKinds : public ::testing::TestWithParam<json> {};

TEST_P(AdjointKinds, TheObjectiveFallsAndTheStencilIsSimulated) {
  json design = small_design(GetParam(), 12);
  design["design"].update({{"method", "adjoint"}, {"density_cell", 25}});
  const DesignResult d = run_design(parse_design(design));
  EXPECT_EQ(d.method, "adjoint");
  ASSERT_GE(d.history.size(), 3u);
  const DesignIteration& first = d.history.front();
  ASSERT_EQ(first.stage, "density");
  double best = first.objective;
  for (const DesignIteration& it : d.history)
    if (it.stage == "density" && it.note.empty()) best = std::min(best, it.objective);
  EXPECT_LT(best, 0.9 * first.objective) << "the objective did not fall by 10 %";
  for (const DesignIteration& it : d.history)
    if (it.stage == "density") {
      EXPECT_NE(it.note, "no stable equilibrium") << it.index;
    }
  const DesignIteration& last = d.history.back();
  EXPECT_EQ(last.stage, "stencil");
  EXPECT_TRUE(std::isfinite(d.rms_error));
  EXPECT_GT(d.rms_error, 0.0);
  EXPECT_GT(d.density_rms_error, 0.0);
  EXPECT_EQ(d.density.value.size(), 64);
  EXPECT_GE(d.density.value.minCoeff(), 0.0);
  EXPECT_LE(d.density.value.maxCoeff(), 1.0);
  // The calibration ran (its own test checks what it measures).
  ASSERT_GE(d.calibration_share.size(), 3u);
  EXPECT_EQ(d.calibration_density.back(), 1.0);
  std::printf(
      "%s: objective %.4g -> %.4g; density design %.2f %%, its stencil %.2f %% (flat %.2f %%)\n",
      GetParam().begin().key().c_str(), first.objective, best, d.density_rms_error, d.rms_error,
      d.flat_error);
}

INSTANTIATE_TEST_SUITE_P(Targets, AdjointKinds,
                         ::testing::Values(json{{"cap", {{"diameter", 130}, {"height", 20}}}},
                                           json{{"saddle", {{"size", 150}, {"height", 15}}}},
                                           json{{"cylinder", {{"size", 150}, {"height", 20}}}}),
                         [](const auto& param_info) { return param_info.param.begin().key(); });

// Stage 3's stencil trials: the calibrated stencil and its neighbours with the densities scaled
// by 0.85 and 1.15, each simulated from flat; the design is the best that settled, and the
// report's stencil entries say which scale each was.
TEST(InverseDesign, TheAdjointKeepsTheBestOfItsStencilTrials) {
  const DesignResult d = run_design(
      parse_design(small_adjoint_design({{"saddle", {{"size", 150}, {"height", 15}}}}, 3, 0)));
  std::vector<const DesignIteration*> stencils;
  for (const DesignIteration& it : d.history)
    if (it.stage == "stencil") stencils.push_back(&it);
  ASSERT_EQ(stencils.size(), 3u);
  EXPECT_EQ(stencils[0]->scale, 1.0);
  EXPECT_EQ(stencils[1]->scale, 0.85);
  EXPECT_EQ(stencils[2]->scale, 1.15);
  EXPECT_TRUE(stencils[0]->best);  // the first is the best so far when it is made
  // More resin, more pieces or larger ones: the shares follow the scale.
  EXPECT_LT(stencils[1]->resin_share, stencils[0]->resin_share);
  EXPECT_GT(stencils[2]->resin_share, stencils[0]->resin_share);
  double best = std::numeric_limits<double>::infinity();
  for (const DesignIteration* it : stencils)
    if (it->note.empty()) best = std::min(best, it->rms_error);
  ASSERT_TRUE(std::isfinite(best)) << "no stencil settled";
  EXPECT_DOUBLE_EQ(d.rms_error, best);
  EXPECT_TRUE(stencils.back()->best == (stencils.back()->rms_error == best));
  // The scene written is the chosen stencil's, whichever trial it was.
  expect_scene_reproduces_form(d);
  std::printf("stencils: %.2f %%, %.2f %%, %.2f %% -> %.2f %%\n", stencils[0]->rms_error,
              stencils[1]->rms_error, stencils[2]->rms_error, d.rms_error);
}

// Stage 3's sizing: after the trials, the pieces' iterates ("pieces", numbered on), the objective
// falling along the better trial's branch, then the sized stencil released from flat, carrying
// that trial's scale; the design is the closer of the two, and its scene reproduces its form.
TEST(InverseDesign, TheAdjointSizesTheBestTrialsPieces) {
  const DesignResult d = run_design(
      parse_design(small_adjoint_design({{"cylinder", {{"size", 150}, {"height", 20}}}}, 2, 8)));
  std::vector<const DesignIteration*> pieces, stencils;
  for (size_t k = 0; k < d.history.size(); ++k) {
    const DesignIteration& it = d.history[k];
    EXPECT_EQ(it.index, static_cast<int>(k));
    if (it.stage == "pieces") pieces.push_back(&it);
    if (it.stage == "stencil") stencils.push_back(&it);
  }
  ASSERT_GE(pieces.size(), 2u);
  ASSERT_EQ(stencils.size(), 3u) << "two trials, then the sized stencil";
  EXPECT_LT(stencils[1], pieces.front());
  EXPECT_GT(stencils[2], pieces.back());
  ASSERT_TRUE(stencils[0]->note.empty() && stencils[1]->note.empty()) << "a trial did not settle";
  const DesignIteration* trial =
      stencils[1]->rms_error < stencils[0]->rms_error ? stencils[1] : stencils[0];
  EXPECT_EQ(stencils[2]->scale, trial->scale);  // 1 or 0.85
  double best = pieces.front()->objective;
  for (const DesignIteration* it : pieces)
    if (it->note.empty()) best = std::min(best, it->objective);
  EXPECT_LT(best, pieces.front()->objective) << "no size did better along the branch";
  EXPECT_EQ(stencils[2]->note.rfind("piece sizes refined (on the branch: ", 0), 0u)
      << stencils[2]->note;
  EXPECT_DOUBLE_EQ(d.rms_error, std::min(trial->rms_error, stencils[2]->rms_error));
  expect_scene_reproduces_form(d);
  std::printf("trials %.2f, %.2f %%, sized %.2f %% (%s): objective %.4g -> %.4g\n",
              stencils[0]->rms_error, stencils[1]->rms_error, stencils[2]->rms_error,
              stencils[2]->note.c_str(), pieces.front()->objective, best);
}

TEST(InverseDesign, TheStencilsSceneReproducesTheReportedForm) {
  const DesignResult d =
      run_design(parse_design(small_design({{"cap", {{"diameter", 160}, {"height", 24}}}}, 2)));
  expect_scene_reproduces_form(d);
}

// A coat on one face under a stretch across the target's ridges (155 mm frame, latex stretched
// along x only), on an 11 x 11 sheet.
json coated_design(const json& target, double lambda, const char* side) {
  json design = small_design(target, 12);
  design["frame"] = {{"size", 155}, {"lambda", {lambda, 1.0}}};
  design["resin"] = {{"min_feature", 4}, {"cell", 20}, {"bilayer", true}, {"resin_side", side}};
  return design;
}

// A cylinder is the curl of a coat on one face: the whole sheet coated under a stretch of 1.7
// across the axis rises to the target's radius, within the goal (measured 0.79 % against a flat
// sheet's 4.0 %). Every density the search tries lays out that same full coat, and the search
// does not simulate a stencil it has simulated already.
TEST(InverseDesign, ACoatOnOneFaceMakesACylinder) {
  const DesignResult d = run_design(
      parse_design(coated_design({{"cylinder", {{"size", 150}, {"height", 20}}}}, 1.7, "top")));
  expect_meets_goal(d);
  EXPECT_DOUBLE_EQ(d.stencil.resin_share, 1.0);
  EXPECT_LT(d.history.size(), 4u);
}

// A cap bulges up everywhere, rim included: every piece of a convex stencil goes on top (the
// Laplacian is taken a step inwards near the rim, where the target's height beyond it is flat).
TEST(InverseDesign, ConvexFacesOfACapAreAllOnTop) {
  json design = small_design({{"cap", {{"diameter", 160}, {"height", 24}}}});
  design["resin"].update({{"bilayer", true}, {"resin_side", "convex"}});
  const DesignSpec spec = parse_design(design);
  const TargetSurface target = make_target(spec.target);
  const Stencil s = design_stencil(spec, target, [](const Vec2&) { return 0.5; });
  ASSERT_GT(s.pieces, 20);
  for (const StencilSquare& q : s.squares) EXPECT_EQ(q.face, +1) << q.centre.transpose();
}

// The pre-stretch searched: from a stretch of 1.3, too little for the cylinder's radius, the
// search raises it (measured at 17²: 1.30 -> 1.75, 2.26 -> 0.65 %) and the stencil's scene, with
// the stretch it was simulated at, reproduces the form.
TEST(InverseDesign, TheSearchFindsTheStretchACoatNeeds) {
  json design = coated_design({{"cylinder", {{"size", 150}, {"height", 20}}}}, 1.3, "top");
  const DesignResult fixed = run_design(parse_design(design));
  design["design"]["search_stretch"] = true;
  const DesignResult searched = run_design(parse_design(design));
  EXPECT_GT(searched.spec.lambda.x(), 1.5);
  EXPECT_EQ(searched.spec.lambda.y(), 1.0);
  EXPECT_LT(searched.rms_error, 0.5 * fixed.rms_error);
  EXPECT_LT(searched.rms_error, 2.0);
  EXPECT_NEAR(searched.best.stretch, (searched.spec.lambda.x() - 1.0) / 0.3, 1e-12);
  expect_scene_reproduces_form(searched);
}

// A design with darts on a 17 x 17 sheet: the frame (mm) and its stretch, the layout and how many.
json darts_design(const json& target, int evaluations, double frame, const json& lambda,
                  const char* layout, int darts) {
  json design = small_design(target, evaluations);
  design["frame"] = {{"size", frame}, {"lambda", lambda}};
  design["sheet"]["resolution"] = 17;
  design["resin"].update({{"layout", layout}, {"darts", darts}});
  return design;
}

// Darts make a dome: the bundled cap (160 mm across, 24 mm high) on a 170 mm frame — the cap's
// width measured along its surface — stretched 1.15 x 1.15, on a 17 x 17 sheet, comes within the
// goal (measured 1.40 %, a flat sheet 4.37 %; squares on this sheet reached 1.84 % at best) as
// a dome, and the scene reproduces it. The search moves only the darts' scale.
TEST(InverseDesign, DartsMakeADome) {
  const DesignResult d = run_design(parse_design(darts_design(
      {{"cap", {{"diameter", 160}, {"height", 24}}}}, 6, 170, {1.15, 1.15}, "darts", 6)));
  expect_meets_goal(d);
  EXPECT_GT(d.stencil.resin_share, 0.5);
  EXPECT_LT(d.stencil.resin_share, 0.95);
  EXPECT_EQ(d.run.form_global, "synclastic");
  // Each simulation a scale of its own (none laid out the same darts twice).
  for (size_t i = 0; i < d.history.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      EXPECT_NE(d.history[i].parameters.darts, d.history[j].parameters.darts);
  EXPECT_NE(d.best.darts, 1.0);
  EXPECT_TRUE(d.message.empty()) << d.message;  // the frame fits
  expect_scene_reproduces_form(d);
}

// Fisheye darts make a saddle: the bundled one (150 mm square, +-15 mm) on a 155 mm frame stretched
// 1.1 along x only, three lenses of latex across the stretch, on a 17 x 17 sheet, comes within
// the goal in four simulations (measured 1.80 % at a scale of 0.75, a flat sheet 4.29 %; squares
// never came closer than flat), an anticlastic form, and the scene reproduces it.
TEST(InverseDesign, FisheyeDartsMakeASaddle) {
  const DesignResult d = run_design(parse_design(darts_design(
      {{"saddle", {{"size", 150}, {"height", 15}}}}, 4, 155, {1.1, 1.0}, "fisheye_darts", 3)));
  expect_meets_goal(d);
  EXPECT_EQ(d.run.form_global, "anticlastic");
  EXPECT_EQ(d.stencil.spec.parts.size(), 4u);  // the sheet less three lenses
  EXPECT_TRUE(d.message.empty()) << d.message;
  expect_scene_reproduces_form(d);
}

// The free form (two bumps and a valley) as examples/inverse_freeform.json makes it, on 17 x 17:
// darts about the peaks "auto" finds (its bumps and its valley's middle) cut through a coat on
// the face it bulges towards, 155 mm frame at 1.2 x 1.2, four darts each. Measured 1.23 % at the
// first scale (a flat sheet 2.63 %; hand-placed darts without a coat 1.42 %). Two impregnate
// steps, one per face, reproduce the form.
TEST(InverseDesign, DartsThroughAConvexCoatMakeTheFreeForm) {
  const json target = {{"height_field",
                        {{"size", 150},
                         {"z",
                          "12*exp(-((x-35)^2+(y-20)^2)/800) + 10*exp(-((x+35)^2+(y+25)^2)/800) - "
                          "6*exp(-((x-y)^2)/1000)"}}}};
  json design = darts_design(target, 3, 155, {1.2, 1.2}, "darts", 4);
  design["resin"].update(
      {{"cell", 20}, {"bilayer", true}, {"resin_side", "convex"}, {"dart_centres", "auto"}});
  const DesignResult d = run_design(parse_design(design));
  expect_meets_goal(d);
  // The centres found: the bumps' tops and the valley's middle (dart_layout_test.cpp).
  EXPECT_EQ(d.spec.layout.centres.size(), 3u);
  EXPECT_NE(d.message.find("Darts about 3 centres"), std::string::npos) << d.message;
  EXPECT_EQ(d.stencil.pieces, 2);
  EXPECT_EQ(d.stencil.pieces_bottom(), 1);
  int coats = 0;
  const json scene = design_scene(d.spec, d.stencil);
  for (const json& step : scene["protocol"])
    coats += step["step"] == "impregnate" && step["bilayer"] == true ? 1 : 0;
  EXPECT_EQ(coats, 2);
  expect_scene_reproduces_form(d);
}

// The bundled OBJ target (a twisted wave) by a coat on the face it bulges towards, cell by cell, on
// a 155 mm frame stretched 1.3 x 1.3 (examples/inverse_obj.json) on a 17 x 17 sheet: within the
// goal at its first stencil, the whole sheet coated (measured 1.70 %; a flat sheet 4.80 %).
TEST(InverseDesign, AConvexCoatMakesTheTwistedWave) {
  const std::filesystem::path examples = std::filesystem::path(MEMBRA_SOURCE_DIR) / "examples";
  json design;
  std::ifstream(examples / "inverse_obj.json") >> design;
  design["sheet"]["resolution"] = 17;
  design["design"]["evaluations"] = 1;
  const DesignResult d = run_design(parse_design(design, examples));
  expect_meets_goal(d);
  EXPECT_GT(d.stencil.pieces_bottom(), 0);
  EXPECT_LT(d.stencil.pieces_bottom(), d.stencil.pieces);
}

// Darts about two centres on a target with two domes: 17 x 17 sheet, 155 mm frame at 1.1 x 1.1,
// four darts each. Measured 1.81 % with two centres (3.15 % with one, a flat sheet 3.99 %).
// A centre outside the target's footprint is refused, naming it.
TEST(InverseDesign, DartsAboutTwoCentresComeCloserThanOne) {
  const json target = {
      {"height_field",
       {{"size", 150}, {"z", "20*exp(-((x-40)^2+y^2)/1800) + 20*exp(-((x+40)^2+y^2)/1800)"}}}};
  json design = darts_design(target, 4, 155, {1.1, 1.1}, "darts", 4);
  design["resin"]["dart_centres"] = {{40, 0}, {-40, 0}};
  const DesignResult two = run_design(parse_design(design));
  design["resin"].erase("dart_centres");
  const DesignResult one = run_design(parse_design(design));
  EXPECT_LT(two.rms_error, 0.5 * two.flat_error);
  EXPECT_LT(two.rms_error, 0.75 * one.rms_error);
  EXPECT_EQ(two.run.form_global, "synclastic");
  design["resin"]["dart_centres"] = {{40, 0}, {90, 0}};
  try {
    run_design(parse_design(design));
    ADD_FAILURE() << "a centre outside the footprint was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/resin/dart_centres/1"), std::string::npos) << e.what();
  }
}

// Fisheye darts size their lenses for latex that shrinks along the rows only: under a stretch of
// both axes the design says so; a dome's darts on a frame wider than the cap measured along its
// surface (200 against 169 mm) name the frame that fits; and darts on a saddle, whose circles are
// longer than on a plane, say they have no width there.
TEST(InverseDesign, DartsSayWhenTheFrameDoesNotSuitThem) {
  json design = small_design({{"saddle", {{"size", 150}, {"height", 15}}}}, 1);
  design["resin"].update({{"layout", "fisheye_darts"}, {"darts", 3}});
  DesignResult d = run_design(parse_design(design));
  EXPECT_NE(d.message.find("stretched along one axis"), std::string::npos) << d.message;
  design = small_design({{"cap", {{"diameter", 160}, {"height", 24}}}}, 1);
  design["resin"].update({{"layout", "darts"}});
  d = run_design(parse_design(design));
  EXPECT_NE(d.message.find("a frame 169 mm across"), std::string::npos) << d.message;
  design = small_design({{"saddle", {{"size", 150}, {"height", 15}}}}, 1);
  design["resin"].update({{"layout", "darts"}});
  d = run_design(parse_design(design));
  EXPECT_NE(d.message.find("nowhere shorter"), std::string::npos) << d.message;
}

// "resin_side": "convex" on an S-shaped wave, z = 5 sin(pi x / 75) mm: the pieces under its crest
// (x > 0) go on top, those under its trough underneath, one impregnate step per face, and the
// form comes within 1 % of the target (measured 0.66 %; a flat sheet 1.53 %), where the same coat
// all on top rolls the sheet one way (4.06 %). The stencil's scene reproduces the form.
TEST(InverseDesign, ConvexFacesFollowTheTargetsCurvature) {
  const json wave = {{"height_field", {{"size", 150}, {"z", "5*sin(pi*x/75)"}}}};
  const DesignResult convex = run_design(parse_design(coated_design(wave, 1.8, "convex")));
  const DesignResult top = run_design(parse_design(coated_design(wave, 1.8, "top")));
  const double middle = 0.5 * 0.155;
  int bottom = 0;
  for (const StencilSquare& q : convex.stencil.squares) {
    EXPECT_EQ(q.face, q.centre.x() > middle ? +1 : -1) << q.centre.transpose();
    bottom += q.face < 0;
  }
  EXPECT_GT(bottom, 0);
  std::vector<int> sides;
  for (const ProtocolStep& step : convex.scene.protocol)
    if (const auto* i = step.as<ImpregnateStep>()) {
      EXPECT_TRUE(i->bilayer);
      sides.push_back(i->resin_side);
    }
  EXPECT_EQ(sides, (std::vector<int>{+1, -1}));
  EXPECT_LT(convex.rms_error, 1.0);
  EXPECT_LT(convex.rms_error, 0.5 * convex.flat_error);
  EXPECT_GT(top.rms_error, 2.0 * convex.rms_error);
  expect_scene_reproduces_form(convex);
}

// An elongated natural sheet (86 x 155 mm) on a coarse grid: 9 particles across would leave
// cells 3 % longer than wide, which scenes refuse; the design takes the first finer grid whose
// cells are square (11 across, 19 along), and keeps the requested grid where it fits (17: 30).
TEST(InverseDesign, AnElongatedSheetGetsSquareCells) {
  json design = coated_design({{"cylinder", {{"size", 150}, {"height", 20}}}}, 1.8, "top");
  design["sheet"]["resolution"] = 9;
  EXPECT_EQ(parse_design(design).scene.grid.nx, 11);
  EXPECT_EQ(parse_design(design).scene.grid.ny, 19);
  design["sheet"]["resolution"] = 17;
  EXPECT_EQ(parse_design(design).scene.grid.nx, 17);
  EXPECT_EQ(parse_design(design).scene.grid.ny, 30);
}

TEST(InverseDesign, AnUnreachableTargetSaysWhyAndGivesItsBestAttempt) {
  // A hemisphere 190 mm across has more area than the 200 mm frame's disk.
  const DesignResult d =
      run_design(parse_design(small_design({{"cap", {{"diameter", 190}, {"height", 95}}}}, 2)));
  EXPECT_FALSE(d.reachable);
  EXPECT_NE(d.message.find("more than the stretched frame"), std::string::npos) << d.message;
  EXPECT_FALSE(d.scene.protocol.empty());
  // Every start lays out the same full stencil (as much resin as there can be), simulated once.
  EXPECT_EQ(d.history.size(), 1u);
  EXPECT_EQ(d.start.mean, 1.0);
}

TEST(InverseDesign, BadDesignFilesNameTheField) {
  auto error_of = [](json j) {
    try {
      parse_design(j);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  json j = small_design({{"torus", {{"size", 100}}}});
  EXPECT_NE(error_of(j).find("/target"), std::string::npos);
  j = small_design({{"cap", {{"diameter", 250}, {"height", 20}}}});
  EXPECT_NE(error_of(j).find("wider than the frame"), std::string::npos);
  j = small_design({{"cap", {{"diameter", 100}, {"height", 20}}}});
  j["resin"]["cell"] = 6;
  EXPECT_NE(error_of(j).find("/resin/cell"), std::string::npos);
  j = small_design({{"cap", {{"diameter", 100}, {"height", 60}}}});
  EXPECT_NE(error_of(j).find("/target/cap/height"), std::string::npos);
  j = small_design({{"cap", {{"diameter", 100}, {"height", 20}}}});
  j["frame"]["lambda"] = {0.5, 1.5};
  EXPECT_NE(error_of(j).find("/frame/lambda"), std::string::npos);
  j["frame"]["lambda"] = {1.5, 1.5};
  j["resin"]["resin_side"] = "convex";  // needs a coat on one face
  EXPECT_NE(error_of(j).find("/resin/resin_side"), std::string::npos);
  j["resin"]["bilayer"] = true;
  EXPECT_EQ(parse_design(j).resin_side, "convex");
  j["resin"]["layout"] = "darts";  // darts through a coat on either face
  EXPECT_EQ(parse_design(j).resin_side, "convex");
  j["resin"]["layout"] = "fisheye_darts";  // on one face only
  EXPECT_NE(error_of(j).find("/resin/resin_side"), std::string::npos);
  j["resin"]["layout"] = "darts";
  j["resin"].erase("resin_side");
  j["resin"]["layout"] = "rings";
  EXPECT_NE(error_of(j).find("/resin/layout"), std::string::npos);
  j["resin"]["layout"] = "darts";
  EXPECT_EQ(parse_design(j).layout.kind, "darts");
  j["resin"]["layout"] = "darts";
  j["resin"]["darts"] = 2;
  EXPECT_NE(error_of(j).find("/resin/darts"), std::string::npos);
  j["resin"]["layout"] = "fisheye_darts";
  j["resin"]["darts"] = 64;  // 200 mm frame: 200 / 64 < 2 x 4 mm across it
  EXPECT_NE(error_of(j).find("too many darts"), std::string::npos);
  j["resin"]["darts"] = 3;  // a cap's sheet is a disk
  EXPECT_NE(error_of(j).find("/resin/layout"), std::string::npos);
  j["resin"]["layout"] = "squares";  // darts count darts only
  EXPECT_NE(error_of(j).find("/resin/darts"), std::string::npos);
  j["resin"].erase("darts");
  j["resin"]["dart_centres"] = {{30, 0}, {-30, 0}};  // darts' centres without darts
  EXPECT_NE(error_of(j).find("/resin/dart_centres"), std::string::npos);
  j["resin"]["layout"] = "darts";
  EXPECT_EQ(parse_design(j).layout.centres.size(), 2u);
  j["resin"]["dart_centres"] = {{30, 0}, {20, 0}};  // 10 mm apart, min_feature 4 mm
  EXPECT_NE(error_of(j).find("/resin/dart_centres/1"), std::string::npos);
  j["resin"]["dart_centres"] = {{30, 0}, {"a", 0}};
  EXPECT_NE(error_of(j).find("/resin/dart_centres/1/0"), std::string::npos);
  j["resin"]["dart_centres"] = "where the bumps are";  // "auto" or points
  EXPECT_NE(error_of(j).find("/resin/dart_centres"), std::string::npos);
  j["resin"]["dart_centres"] = "auto";
  EXPECT_TRUE(parse_design(j).layout.auto_centres);
  j["resin"].erase("dart_centres");
  j["resin"]["layout"] = "squares";
  j["resin"]["layout"] = "darts";
  j["resin"]["darts"] = 8;
  j["resin"].erase("bilayer");
  j["design"]["method"] = "adjoint";  // lays out squares only
  EXPECT_NE(error_of(j).find("/resin/layout"), std::string::npos);
  j["resin"].erase("layout");
  j["resin"].erase("darts");
  j["design"]["method"] = "adjoint";  // keeps the stretch
  j["design"]["search_stretch"] = true;
  EXPECT_NE(error_of(j).find("/design/search_stretch"), std::string::npos);
  j["design"].erase("search_stretch");
  j["design"]["method"] = "gradient";
  EXPECT_NE(error_of(j).find("/design/method"), std::string::npos);
  j["design"]["method"] = "adjoint";
  j["design"]["density_cell"] = 150;  // more than half the frame
  EXPECT_NE(error_of(j).find("/design/density_cell"), std::string::npos);
  j["design"]["density_cell"] = 20;
  j["design"]["smoothing"] = -1;
  EXPECT_NE(error_of(j).find("/design/smoothing"), std::string::npos);
  j["design"].erase("smoothing");
  j["design"]["flattening"] = "lscm";  // conformal or projection
  EXPECT_NE(error_of(j).find("/design/flattening"), std::string::npos);
  j["design"].erase("flattening");
  for (int trials : {0, 6}) {  // one to five stencils
    j["design"]["stencil_trials"] = trials;
    EXPECT_NE(error_of(j).find("/design/stencil_trials"), std::string::npos) << trials;
  }
  j["design"]["stencil_trials"] = 2;
  EXPECT_EQ(parse_design(j).stencil_trials, 2);
  j["design"].erase("stencil_trials");
  EXPECT_EQ(parse_design(j).stencil_trials, 5);
  for (double evaluations : {-1.0, 1001.0, 2.5}) {  // a whole number from 0 (off) to 1000
    j["design"]["piece_evaluations"] = evaluations;
    EXPECT_NE(error_of(j).find("/design/piece_evaluations"), std::string::npos) << evaluations;
  }
  j["design"]["piece_evaluations"] = 0;
  EXPECT_EQ(parse_design(j).piece_evaluations, 0);
  j["design"].erase("piece_evaluations");
  EXPECT_EQ(parse_design(j).piece_evaluations, 20);
  j["resin"]["bilayer"] = true;  // not placed by the adjoint yet
  EXPECT_NE(error_of(j).find("/resin/bilayer"), std::string::npos);
  j["resin"].erase("bilayer");
  EXPECT_EQ(parse_design(j).evaluations, 6);  // given
  j["design"].erase("evaluations");
  EXPECT_EQ(parse_design(j).evaluations, 80);  // the adjoint's default
  j["frame"]["lambda"] = {1.0, 1.0};           // nothing stretched: resin would change nothing
  EXPECT_NE(error_of(j).find("/frame/lambda"), std::string::npos);
  // A uniaxial stretch is fine; the sheet is then 133 x 200 mm, with square cells.
  j["frame"]["lambda"] = {1.5, 1.0};
  const json scene = design_scene(parse_design(j), Stencil{});
  EXPECT_EQ(scene["sheet"]["resolution"], json({11, 16}));
  EXPECT_NO_THROW(parse_scene(scene));
  j = small_design({{"cap", {{"diameter", 100}, {"height", 20}}}});
  j["resin"]["material"] = "unobtainium";
  EXPECT_NE(error_of(j).find("material"), std::string::npos);
  j = small_design({{"cap", {{"diameter", 100}, {"height", 20}}}});
  j["resin"]["resin_side"] = "left";
  EXPECT_NE(error_of(j).find("/resin/resin_side"), std::string::npos);
  // The face and the bilayer reach the stencil's impregnate step.
  j["resin"]["resin_side"] = "bottom";
  j["resin"]["bilayer"] = true;
  const Stencil st =
      stencil_of({{Vec2(0.01, 0.01), Vec2(0.05, 0.01), Vec2(0.05, 0.05), Vec2(0.01, 0.05)}});
  const json coated = design_scene(parse_design(j), st);
  EXPECT_EQ(coated["protocol"][1]["resin_side"], "bottom");
  EXPECT_EQ(coated["protocol"][1]["bilayer"], true);
  EXPECT_TRUE(parse_scene(coated).protocol[1].as<ImpregnateStep>()->bilayer);
}

TEST(InverseDesign, ObjAndHeightFieldTargetsWorkLikeTheAnalyticOnes) {
  // The same saddle three ways: analytic, as a formula, and as an OBJ written from the first.
  TargetSpec spec;
  spec.kind = "saddle";
  spec.size = 0.15;
  spec.height = 0.015;
  const TargetSurface analytic = make_target(spec);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("membra_obj_target_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  {
    std::ofstream out(dir / "saddle.obj");
    write_obj(out, analytic.x, analytic.triangles);
  }
  const json formula = {{"height_field", {{"size", 150}, {"z", "15*(x^2 - y^2)/75^2"}}}};
  const json obj = {{"obj", {{"file", "saddle.obj"}}}};
  const DesignResult a =
      run_design(parse_design(small_design({{"saddle", {{"size", 150}, {"height", 15}}}}, 1), dir));
  const DesignResult f = run_design(parse_design(small_design(formula, 1), dir));
  const DesignResult o = run_design(parse_design(small_design(obj, 1), dir));
  std::filesystem::remove_all(dir);
  // One simulation each, of the same stencil (same area, same mean curvature): the same error,
  // up to where the alignment stops (the saddle lets it slide a little) and the release's
  // round-off (measured 0.007 % on one machine, 0.9 % on an AMD EPYC: 5.590 against 5.641 mm).
  // Within 2 %.
  EXPECT_NEAR(f.target.area, a.target.area, 1e-9);
  EXPECT_NEAR(o.target.area, a.target.area, 1e-9);
  EXPECT_NEAR(o.target.diameter, 0.15, 1e-9);
  EXPECT_NEAR(f.rms_error / a.rms_error, 1.0, 0.02);
  EXPECT_NEAR(o.rms_error / a.rms_error, 1.0, 0.02);
  // A missing OBJ is an input error naming the field.
  EXPECT_THROW(parse_design(small_design({{"obj", {{"file", "nowhere.obj"}}}}), dir), InputError);
}

}  // namespace
}  // namespace membra
