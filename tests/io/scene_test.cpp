// Scene parsing: values converted to SI, and every bad input named by its JSON pointer.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "test_util.hpp"

#include "membra/io/scene.hpp"
#include "membra/process/memory_estimate.hpp"
#include "membra/process/run.hpp"

namespace membra {
namespace {

using nlohmann::json;

json minimal() {
  return json::parse(R"({
    "name": "t",
    "sheet": {"size": [100, 50], "resolution": [11, 6]},
    "pins": [{"corners": true}],
    "simulation": {"solver": "rk4", "T": 2e-4, "D": 3, "G": 9.81, "steps": 10}
  })");
}

// The InputError's location, or "" when parsing succeeded.
std::string error_at(const json& j) {
  try {
    parse_scene(j);
  } catch (const InputError& e) {
    return e.where();
  }
  return "";
}

TEST(Scene, ConvertsToSI) {
  json j = minimal();
  j["materials"] = {{"soft", {{"E", 3.0}, {"thickness", 0.25}, {"density", 1.1}}}};
  j["sheet"]["material"] = "soft";
  j["simulation"]["K"] = 2.0;
  const Scene s = parse_scene(j);
  EXPECT_DOUBLE_EQ(s.grid.width, 0.1);
  EXPECT_DOUBLE_EQ(s.grid.height, 0.05);
  EXPECT_EQ(s.grid.nx, 11);
  EXPECT_DOUBLE_EQ(s.sheet.material.youngs_modulus, 3e6);
  EXPECT_DOUBLE_EQ(s.sheet.material.thickness, 0.25e-3);
  EXPECT_DOUBLE_EQ(s.sheet.material.density, 1100.0);
  EXPECT_DOUBLE_EQ(*s.sheet.stretch_stiffness, 2000.0);  // 2 N/mm
  EXPECT_DOUBLE_EQ(s.simulation.dt, 2e-4);
  EXPECT_DOUBLE_EQ(s.simulation.damping, 3.0);
  EXPECT_EQ(s.simulation.steps, 10);
  ASSERT_EQ(s.pins.size(), 1u);
}

TEST(Scene, PathToleranceDefaultsToTheToleranceAndIsNeverTighter) {
  json j = minimal();
  j["simulation"]["tolerance"] = 1e-8;
  EXPECT_DOUBLE_EQ(parse_scene(j).simulation.path_tolerance, 1e-8);
  j["simulation"]["path_tolerance"] = 1e-4;
  EXPECT_DOUBLE_EQ(parse_scene(j).simulation.path_tolerance, 1e-4);
  j["simulation"]["path_tolerance"] = 1e-10;  // tighter than the final solve: no sense in it
  EXPECT_DOUBLE_EQ(parse_scene(j).simulation.path_tolerance, 1e-8);
  j["simulation"]["path_tolerance"] = -1.0;
  EXPECT_EQ(error_at(j), "/simulation/path_tolerance");
}

// simulation.ramp_seconds: for time stepping only, and within the run's simulated time.
TEST(Scene, ARampNeedsTimeSteppingAndMustFitInTheRun) {
  json j = minimal();
  j["simulation"]["solver"] = "rk4";
  j["simulation"]["T"] = 1e-4;
  j["simulation"]["steps"] = 20000;                               // 2 s
  EXPECT_DOUBLE_EQ(parse_scene(j).simulation.ramp_seconds, 0.0);  // at once by default
  j["simulation"]["ramp_seconds"] = 1.5;
  EXPECT_DOUBLE_EQ(parse_scene(j).simulation.ramp_seconds, 1.5);
  j["simulation"]["ramp_seconds"] = 2.5;  // longer than 2 s of run
  EXPECT_EQ(error_at(j), "/simulation/ramp_seconds");
  j["simulation"]["ramp_seconds"] = -1.0;
  EXPECT_EQ(error_at(j), "/simulation/ramp_seconds");
  j["simulation"]["ramp_seconds"] = 1.0;
  j["simulation"]["solver"] = "static";  // equilibrium solvers follow increments instead
  EXPECT_EQ(error_at(j), "/simulation/ramp_seconds");
}

TEST(Scene, MaterialPresetsCanBePartlyOverridden) {
  json j = minimal();
  j["materials"] = {{"latex", {{"thickness", 1.0}}}};
  const Scene s = parse_scene(j);
  EXPECT_DOUBLE_EQ(s.sheet.material.youngs_modulus, 1.5e6);
  EXPECT_DOUBLE_EQ(s.sheet.material.thickness, 1e-3);
}

TEST(Scene, ReadsTheModelItsMeshAndTheLaws) {
  json j = minimal();
  EXPECT_EQ(parse_scene(j).model, SheetModel::lattice);  // the paper's, by default
  EXPECT_EQ(parse_scene(j).sheet.material.law, MembraneLaw::neo_hookean);  // latex's default
  j["model"] = "continuum";
  j["sheet"].erase("resolution");  // the continuum sheet does without
  j["sheet"]["mesh"] = {{"max_edge", 4}, {"elements_across", 6}};
  j["materials"] = {{"latex", {{"law", "mooney_rivlin"}}}, {"epoxy", {{"law", "linear"}}}};
  const Scene s = parse_scene(j);
  EXPECT_EQ(s.model, SheetModel::continuum);
  EXPECT_DOUBLE_EQ(s.mesh.max_edge, 0.004);
  EXPECT_EQ(s.mesh.elements_across, 6);
  EXPECT_EQ(s.sheet.material.law, MembraneLaw::mooney_rivlin);
  EXPECT_EQ(epoxy().law, MembraneLaw::stvk);  // the resin's default
  EXPECT_EQ(s.sheet.material.wrinkling, Wrinkling::full);
  j["materials"]["latex"]["wrinkling"] = "relaxed";
  EXPECT_EQ(parse_scene(j).sheet.material.wrinkling, Wrinkling::relaxed);
  // --set makes the objects a path needs.
  json k = minimal();
  apply_override(k, "model=continuum");
  apply_override(k, "sheet.mesh.max_edge=4");
  EXPECT_DOUBLE_EQ(parse_scene(k).mesh.max_edge, 0.004);
  EXPECT_EQ(parse_scene(k).model, SheetModel::continuum);
}

// What only the mesher finds is named at the mesh's field, before anything runs.
TEST(Scene, ContinuumMeshErrorsNameTheField) {
  json j = minimal();
  j["model"] = "continuum";
  j["sheet"]["mesh"] = {{"max_edge", 0.01}};  // mm: billions of triangles on 100 x 50 mm
  try {
    prepare_scene(parse_scene(j));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/sheet/mesh");
    EXPECT_NE(e.detail().find("triangles"), std::string::npos) << e.detail();
    EXPECT_NE(e.detail().rfind("about", 0), std::string::npos) << e.detail();
  }
}

TEST(Scene, ErrorsNameTheJsonPointer) {
  struct Case {
    const char* patch;  // JSON merge patch applied to minimal()
    const char* where;
  };
  const Case cases[] = {
      {R"({"sheet": {"resolution": [0, 6]}})", "/sheet/resolution/0"},
      {R"({"sheet": {"resolution": [11, 6.5]}})", "/sheet/resolution/1"},
      {R"({"sheet": {"resolution": [11, 11]}})", "/sheet/resolution"},  // non-square cells
      {R"({"sheet": {"size": [100, -5]}})", "/sheet/size/1"},
      {R"({"sheet": {"size": "big"}})", "/sheet/size"},
      {R"({"sheet": {"colour": "red"}})", "/sheet/colour"},
      {R"({"sheet": {"material": "steel"}})", "/sheet/material"},
      {R"({"materials": {"latex": {"E": -1.5}}})", "/materials/latex/E"},
      {R"({"materials": {"foam": {"E": 1}}})", "/materials/foam/thickness"},
      {R"({"simulation": {"K": -0.5}})", "/simulation/K"},
      {R"({"simulation": {"T": 0}})", "/simulation/T"},
      {R"({"simulation": {"D": -1}})", "/simulation/D"},
      {R"({"simulation": {"solver": "euler"}})", "/simulation/solver"},
      {R"({"simulation": {"steps": -3}})", "/simulation/steps"},
      {R"({"pins": [{"edge": "middle"}]})", "/pins/0/edge"},
      {R"({"pins": [{"point": [500, 10]}]})", "/pins/0/point/0"},
      {R"({"pins": [{"edge": "left", "corners": true}]})", "/pins/0"},
      {R"({"gravity": 1})", "/gravity"},
      {R"({"model": "fem"})", "/model"},
      {R"({"sheet": {"mesh": {"max_edge": -4}}})", "/sheet/mesh/max_edge"},
      {R"({"sheet": {"mesh": {"elements_across": 0}}})", "/sheet/mesh/elements_across"},
      {R"({"sheet": {"mesh": {"size": 4}}})", "/sheet/mesh/size"},
      {R"({"materials": {"latex": {"law": "hooke"}}})", "/materials/latex/law"},
      {R"({"materials": {"latex": {"wrinkling": "some"}}})", "/materials/latex/wrinkling"},
      {R"({"materials": {"epoxy": {"wrinkling": "relaxed"}}})", "/materials/epoxy/wrinkling"},
  };
  for (const auto& c : cases) {
    json j = minimal();
    j.merge_patch(json::parse(c.patch));
    EXPECT_EQ(error_at(j), c.where) << c.patch;
  }
  json j = minimal();
  j.erase("sheet");
  EXPECT_EQ(error_at(j), "/sheet");
}

TEST(Scene, MessagesSayWhatIsWrong) {
  json j = minimal();
  j["simulation"]["K"] = -0.5;
  try {
    parse_scene(j);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "/simulation/K: must be > 0, got -0.5");
  }
}

class SceneFile : public ::testing::Test {
 protected:
  std::filesystem::path dir = unique_temp_dir();
  void SetUp() override { std::filesystem::create_directories(dir); }
  void TearDown() override { std::filesystem::remove_all(dir); }
  std::filesystem::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  }
};

TEST_F(SceneFile, MalformedJsonNamesFileAndLine) {
  const auto f = write("bad.json", "{\n  \"name\": \"x\",\n  \"sheet\": {,}\n}\n");
  try {
    load_scene(f);
    FAIL();
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("bad.json"), std::string::npos) << msg;
    EXPECT_NE(msg.find("malformed JSON"), std::string::npos) << msg;
    EXPECT_NE(msg.find("line 3"), std::string::npos) << msg;
  }
}

TEST_F(SceneFile, FieldErrorsNameFileAndPointer) {
  json j = minimal();
  j["sheet"]["resolution"] = {0, 6};
  const auto f = write("zero.json", j.dump());
  try {
    load_scene(f);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), f.string() + ": /sheet/resolution/0");
  }
}

TEST_F(SceneFile, ABadSetValueNamesTheFlagNotTheFile) {
  const auto f = write("good.json", minimal().dump());
  try {
    load_scene(f, {"sheet.size=abc"});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "--set sheet.size=abc (on " + f.string() + "): /sheet/size");
  }
  try {  // an error of the file itself still names the file
    json j = minimal();
    j["sheet"]["resolution"] = {0, 6};
    load_scene(write("zero.json", j.dump()), {"sheet.size=[100,50]"});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), (dir / "zero.json").string() + ": /sheet/resolution/0");
  }
}

TEST_F(SceneFile, MissingFile) {
  EXPECT_THROW(load_scene(dir / "nope.json"), InputError);
}

TEST_F(SceneFile, OverridesApplyBeforeValidation) {
  const auto f = write("ok.json", minimal().dump());
  const Scene s =
      load_scene(f, {"simulation.steps=77", "sheet.size.0=200", "sheet.resolution=[21,6]"});
  EXPECT_EQ(s.simulation.steps, 77);
  EXPECT_DOUBLE_EQ(s.grid.width, 0.2);
  EXPECT_EQ(s.grid.nx, 21);
  EXPECT_THROW(load_scene(f, {"simulation.steps"}), InputError);
  EXPECT_THROW(load_scene(f, {"simulation.T=-1"}), InputError);
  // A string value that is not JSON is taken as a string.
  EXPECT_EQ(load_scene(f, {"name=plain words"}).name, "plain words");
}

json with_protocol(const json& impregnate_pattern) {
  json j = minimal();
  j["simulation"] = {{"G", 0}};
  j.erase("pins");
  j["protocol"] = {{{"step", "stretch"}, {"lambda", {1.5, 1.0}}},
                   {{"step", "impregnate"}, {"pattern", impregnate_pattern}},
                   {{"step", "release"}, {"increments", 2}}};
  return j;
}

TEST(Scene, ProtocolErrorsNameTheField) {
  const json strip = {{"strip", {{"points", {{0, 25}, {150, 25}}}, {"width", 5}}}};
  EXPECT_EQ(error_at(with_protocol(strip)), "");
  // The frame is 150 x 50 mm after a 1.5 stretch of the 100 x 50 mm sheet.
  EXPECT_EQ(error_at(with_protocol({{"ellipse", {{"center", {400, 25}}, {"radii", {10, 10}}}}})),
            "/protocol/1/pattern");
  EXPECT_EQ(error_at(with_protocol({{"strip", {{"points", {{0, 25}, {150, 25}}}, {"width", 0}}}})),
            "/protocol/1/pattern/strip/width");
  EXPECT_EQ(error_at(with_protocol({{"blob", {}}})), "/protocol/1/pattern/blob");
  EXPECT_EQ(error_at(with_protocol({{"circle", {{"center", {75, 25}}}}})),
            "/protocol/1/pattern/circle/radius");
  EXPECT_EQ(
      error_at(with_protocol({{"union", {strip, {{"polygon", {{"points", {{0, 0}, {1, 1}}}}}}}}})),
      "/protocol/1/pattern/union/1/polygon/points");
  json j = with_protocol(strip);
  j["protocol"][0]["lambda"] = {0, 1};
  EXPECT_EQ(error_at(j), "/protocol/0/lambda/0");
  j = with_protocol(strip);
  j["protocol"][0]["lambda"] = {-1.5, 1};
  EXPECT_EQ(error_at(j), "/protocol/0/lambda/0");
  // A frame only pulls: a lambda below 1 is refused unless it is no more than the free
  // contraction of an incompressible sheet stretched the other way (exp2's [1.5, 0.8165]).
  j = with_protocol(strip);
  j["protocol"][0]["lambda"] = {0.5, 1.0};
  EXPECT_EQ(error_at(j), "/protocol/0/lambda");
  j["protocol"][0]["lambda"] = {1.5, 0.7};
  EXPECT_EQ(error_at(j), "/protocol/0/lambda");
  j["protocol"][0]["lambda"] = {1.5, 0.8165};
  EXPECT_EQ(error_at(j), "");
  j = with_protocol(strip);
  j["protocol"][1]["bilayer"] = "yes";
  EXPECT_EQ(error_at(j), "/protocol/1/bilayer");
  j["protocol"][1]["bilayer"] = true;
  EXPECT_EQ(error_at(j), "");
  j["sheet"]["bending"] = false;  // the hinges need the bending elements to stop the curl
  EXPECT_EQ(error_at(j), "/protocol/1/bilayer");
  j = with_protocol(strip);
  j["protocol"][1]["material"] = "unobtainium";
  EXPECT_EQ(error_at(j), "/protocol/1/material");
  j = with_protocol(strip);
  j["simulation"]["G"] = 9.81;  // released, free, under gravity: no static equilibrium
  EXPECT_EQ(error_at(j), "/protocol/2");
  j["simulation"]["support"] = "table";  // ... unless it rests on a table
  EXPECT_EQ(error_at(j), "");
  j["simulation"]["support"] = "floor";
  EXPECT_EQ(error_at(j), "/simulation/support");
  j["simulation"]["support"] = "table";
  j["simulation"]["G"] = 0;  // a table with nothing to press the piece onto it
  EXPECT_EQ(error_at(j), "/simulation/support");
  j = with_protocol(strip);
  j["simulation"]["G"] = 9.81;
  j["simulation"]["support"] = "table";
  j["protocol"].push_back({{"step", "load"}, {"gravity", 0}});  // would lift it off the table
  EXPECT_EQ(error_at(j), "/protocol/3/gravity");
  j = with_protocol(strip);
  j["protocol"].erase(0);  // release without stretch
  EXPECT_EQ(error_at(j), "/protocol/1");
  j = with_protocol({{"image", {{"file", "no-such-mask.png"}}}});
  EXPECT_EQ(error_at(j), "/protocol/1/pattern/image/file");
}

TEST_F(SceneFile, ColourImageIsRejected) {
  // A 1 x 1 red PNG (uncompressed deflate block), written byte by byte.
  const unsigned char png[] = {
      0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A, 0x00, 0x00, 0x00, 0x0D, 0x49, 0x48,
      0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x02, 0x00, 0x00,
      0x00, 0x90, 0x77, 0x53, 0xDE, 0x00, 0x00, 0x00, 0x0C, 0x49, 0x44, 0x41, 0x54, 0x08,
      0xD7, 0x63, 0xF8, 0xCF, 0xC0, 0x00, 0x00, 0x03, 0x01, 0x01, 0x00, 0x18, 0xDD, 0x8D,
      0xB0, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4E, 0x44, 0xAE, 0x42, 0x60, 0x82};
  std::ofstream(dir / "red.png", std::ios::binary)
      .write(reinterpret_cast<const char*>(png), sizeof png);
  write("junk.png", "this is not an image");
  for (const char* name : {"red.png", "junk.png"}) {
    json j = with_protocol({{"image", {{"file", name}}}});
    try {
      parse_scene(j, dir);
      FAIL() << name;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), "/protocol/1/pattern/image/file") << name;
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      if (std::string(name) == "red.png") {
        EXPECT_NE(std::string(e.what()).find("not grayscale"), std::string::npos) << e.what();
      }
    }
  }
}

// A free sheet (no gravity) and one more step.
json with_step(const json& step) {
  json j = minimal();
  j["simulation"] = {{"solver", "static"}, {"G", 0}};
  j.erase("pins");
  j["protocol"] = json::array({step});
  return j;
}

// The InputError of parsing, or else of running, the scene: where and what.
std::pair<std::string, std::string> failure(const json& j) {
  try {
    run_scene(parse_scene(j));
  } catch (const InputError& e) {
    return {e.where(), e.what()};
  }
  return {"", ""};
}

TEST(Scene, GrowAddSpringsAndCutErrorsNameTheField) {
  const json grow = {{"step", "grow"}, {"factor", "1 + 0.1*sin(pi*x/w)^2"}, {"increments", 1}};
  EXPECT_EQ(error_at(with_step(grow)), "");
  json j = with_step(grow);
  j["protocol"][0]["factor"] = "1 + *x";
  EXPECT_EQ(failure(j).first, "/protocol/0/factor");
  EXPECT_NE(failure(j).second.find("cannot parse"), std::string::npos) << failure(j).second;
  j["protocol"][0]["factor"] = "1 - x/50";  // 0 at x = 50 mm, negative beyond
  EXPECT_EQ(failure(j).first, "/protocol/0/factor");
  EXPECT_NE(failure(j).second.find("positive"), std::string::npos) << failure(j).second;
  j["protocol"][0]["factor"] = {{"preset", "sine"}};
  EXPECT_EQ(failure(j).first, "/protocol/0/factor/preset");
  j["protocol"][0]["factor"] = {{"image", "no-such-field.png"}, {"range", {1, 1.2}}};
  EXPECT_EQ(failure(j).first, "/protocol/0/factor/image");
  j["protocol"][0]["factor"] = {1, 2};
  EXPECT_EQ(failure(j).first, "/protocol/0/factor");
  j = with_step(grow);
  j["protocol"][0]["direction"] = "diagonal";
  EXPECT_EQ(failure(j).first, "/protocol/0/direction");

  const json springs = {{"step", "add_springs"},
                        {"pattern", {{"strip", {{"points", {{0, 20}, {100, 20}}}, {"width", 4}}}}},
                        {"rest_factor", 0.9}};
  EXPECT_EQ(failure(with_step(springs)).first, "");
  j = with_step(springs);
  j["protocol"][0]["rest_factor"] = 0;
  EXPECT_EQ(failure(j).first, "/protocol/0/rest_factor");
  j = with_step(springs);
  j["protocol"][0]["stiffness"] = -1;
  EXPECT_EQ(failure(j).first, "/protocol/0/stiffness");
  j = with_step(springs);
  j["protocol"][0]["pattern"] = {{"circle", {{"center", {55, 25}}, {"radius", 1}}}};
  EXPECT_EQ(failure(j).first, "/protocol/0/pattern");  // between nodes: covers no spring

  const json cut = {{"step", "cut"}, {"line", {{55, 10}, {55, 40}}}};
  EXPECT_EQ(failure(with_step(cut)).first, "");
  j = with_step(cut);
  j["protocol"][0]["line"] = {{200, 10}, {250, 40}};
  EXPECT_EQ(failure(j).first, "/protocol/0/line");
  EXPECT_NE(failure(j).second.find("outside the sheet"), std::string::npos);
  j["protocol"][0]["line"] = {{50, 10}};
  EXPECT_EQ(failure(j).first, "/protocol/0/line");
  j["protocol"][0]["line"] = {{52, 10}, {52, 10}};
  EXPECT_EQ(failure(j).first, "/protocol/0/line/1");
  j = with_step({{"step", "cut"}});
  EXPECT_EQ(failure(j).first, "/protocol/0");
  j = with_step({{"step", "cut"}, {"hole", {{"circle", {{"center", {50, 25}}, {"radius", 500}}}}}});
  EXPECT_EQ(failure(j).first, "/protocol/0/hole");
  EXPECT_NE(failure(j).second.find("whole sheet"), std::string::npos) << failure(j).second;
  j = with_step({{"step", "cut"}, {"hole", {{"circle", {{"center", {55, 25}}, {"radius", 1}}}}}});
  EXPECT_EQ(failure(j).first, "/protocol/0/hole");
  EXPECT_NE(failure(j).second.find("covers no particle"), std::string::npos);
}

TEST(Scene, CutsAndHolesCanComeAfterTheRelease) {
  // A sheet stretched to 150 mm, released (back to 100 x 50 mm, now lying over x = 25..125 mm:
  // it shrinks about its middle), then cut and holed where it now lies.
  json j = with_step({{"step", "stretch"}, {"lambda", {1.5, 1.0}}});
  j["protocol"].push_back({{"step", "release"}, {"increments", 2}});
  j["protocol"].push_back({{"step", "cut"}, {"line", {{55, -5}, {55, 25}}}});
  j["protocol"].push_back(
      {{"step", "cut"}, {"hole", {{"circle", {{"center", {95, 25}}, {"radius", 6}}}}}});
  const RunResult r = run_scene(parse_scene(j));
  ASSERT_TRUE(r.solve.converged) << r.solve.message;
  ASSERT_EQ(r.steps.size(), 4u);
  EXPECT_GT(r.steps[2].springs_cut, 0);
  EXPECT_GT(r.steps[3].particles_removed, 0);
  EXPECT_EQ(r.concentrations.size(), 2u);
  EXPECT_EQ(r.prepared.membrane.sheet.model.num_particles(), 11 * 6 - r.steps[3].particles_removed);
}

TEST(Scene, LargeHolesReportTheEdgeStressExtrapolatedFromOffTheStaircase) {
  // A 120 mm plate pulled 1 % between grips on the left and right, a round hole of 28 mm
  // (7 spacings in radius; the equal-area circle is 15 mm): Heywood's finite-width factor on
  // the gross stress, (2 + (1 - d/W)^3) / (1 - d/W) = 3.23 for d/W = 0.25.
  const json j = json::parse(R"({"name": "hole",
    "sheet": {"size": [120, 120], "resolution": [61, 61]},
    "simulation": {"solver": "newton", "G": 0},
    "protocol": [{"step": "stretch", "lambda": [1.01, 1.0], "hold": ["left", "right"]},
                 {"step": "cut", "hole": {"circle": {"center": [60.6, 60], "radius": 14}}}]})");
  const RunResult r = run_scene(parse_scene(j));
  ASSERT_TRUE(r.solve.converged) << r.solve.message;
  ASSERT_EQ(r.concentrations.size(), 1u);
  const StressConcentration& c = r.concentrations[0];
  ASSERT_TRUE(c.has_edge);
  EXPECT_NEAR(c.hole_radius, 0.015, 0.001);
  const double d_over_w = 2 * c.hole_radius / 0.12;
  const double heywood = (2 + std::pow(1 - d_over_w, 3)) / (1 - d_over_w);
  EXPECT_NEAR(c.edge_concentration / heywood, 1.0, 0.15);
  EXPECT_NEAR(std::abs(std::sin(c.edge_angle)), 1.0, 0.05);  // above or below the hole
}

TEST(Scene, PatternCoveringNoSpringIsReportedWhenRun) {
  // A 1 mm dot between grid nodes (spacing 10 mm x 1.5): inside the frame, but touches nothing.
  json j = with_protocol({{"ellipse", {{"center", {7.5, 5}}, {"radii", {0.5, 0.5}}}}});
  const Scene s = parse_scene(j);
  try {
    run_scene(s);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/protocol/1/pattern");
  }
}

TEST(Scene, PinsThatSelectNothingAreReportedAtPins) {
  json j = minimal();
  j["pins"] = {{{"box", {1, 1, 2, 2}}}};  // between nodes (spacing 10 mm)
  const Scene s = parse_scene(j);
  try {
    prepare_scene(s);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/pins");
  }
}

}  // namespace
}  // namespace membra

namespace membra {
namespace {

TEST(MemoryEstimate, RefusesGridsTheMachineCannotHold) {
  Scene s = parse_scene(minimal());
  s.grid.nx = s.grid.ny = 1001;  // a million particles
  EXPECT_NEAR(estimate_memory(s), 1.0e6 * 2.5e3 + 64e6, 1e7);
  EXPECT_NO_THROW(check_memory(s, 8e9));
  try {
    check_memory(s, 1e9);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/sheet/resolution");
    EXPECT_NE(std::string(e.what()).find("2.57 GB"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("1 GB"), std::string::npos) << e.what();
  }
  s.simulation.solver = Solver::newton;
  EXPECT_THROW(check_memory(s, 8e9), InputError);
  EXPECT_GT(machine_memory(), 1e8);  // this machine reports its memory
}

}  // namespace
}  // namespace membra

namespace membra {
namespace scene_self_contact_test {

// simulation.self_contact: true (defaults) or an object in mm and kPa; only on the continuum
// sheet and with Newton, and with an exclusion no smaller than the gap.
TEST(Scene, ReadsSelfContactAndSaysWhereItCannotHold) {
  json j = json::parse(R"({
    "name": "t", "model": "continuum", "sheet": {"size": [100, 50], "resolution": [11, 6]},
    "simulation": {"solver": "newton", "G": 0, "self_contact": true}
  })");
  SelfContactSpec c = parse_scene(j).simulation.self_contact;
  EXPECT_TRUE(c.on);
  EXPECT_DOUBLE_EQ(c.gap, 1e-3);
  EXPECT_DOUBLE_EQ(c.exclusion, 3e-3);
  j["simulation"]["self_contact"] = {{"gap", 0.5}, {"pressure", 2.0}};
  c = parse_scene(j).simulation.self_contact;
  EXPECT_DOUBLE_EQ(c.gap, 5e-4);
  EXPECT_DOUBLE_EQ(c.pressure, 2000.0);
  EXPECT_DOUBLE_EQ(c.exclusion, 1.5e-3);
  j["simulation"]["self_contact"] = false;
  EXPECT_FALSE(parse_scene(j).simulation.self_contact.on);
  auto where = [](const json& scene) {
    try {
      parse_scene(scene);
    } catch (const InputError& e) {
      return e.where();
    }
    return std::string();
  };
  j["simulation"]["self_contact"] = {{"gap", 1.0}, {"exclusion", 1.5}};  // under two gaps
  EXPECT_EQ(where(j), "/simulation/self_contact/exclusion");
  j["simulation"]["self_contact"] = {{"gap", -1.0}};
  EXPECT_EQ(where(j), "/simulation/self_contact/gap");
  j["simulation"]["self_contact"] = true;
  j["simulation"]["solver"] = "static";
  EXPECT_EQ(where(j), "/simulation/self_contact");
  j["simulation"]["solver"] = "newton";
  j["model"] = "lattice";
  EXPECT_EQ(where(j), "/simulation/self_contact");
}

}  // namespace scene_self_contact_test
}  // namespace membra
