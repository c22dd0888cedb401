// The scene writer is the reader's inverse: every example read, written and read again gives the
// same typed scene (compared through a second writing, which spells out every field, and through
// the membrane it builds), and a written scene runs to the same form as the original.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "membra/io/scene.hpp"
#include "membra/io/scene_writer.hpp"
#include "membra/process/run.hpp"

namespace membra {
namespace {
using nlohmann::json;
namespace fs = std::filesystem;

const fs::path kWriterExamples = fs::path(MEMBRA_SOURCE_DIR) / "examples";

std::vector<std::string> example_scenes() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(kWriterExamples))
    if (e.path().extension() == ".json" && e.path().stem().string().rfind("inverse_", 0) != 0)
      names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

class RoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(RoundTrip, ReadWriteReadGivesTheSameScene) {
  const Scene first = load_scene(kWriterExamples / GetParam());
  const json written = write_scene(first);
  const Scene second = parse_scene(written, kWriterExamples);
  // The writer writes every field: equal writings are equal scenes, to the last bit of every
  // number (the writer picks decimals that read back exactly).
  EXPECT_EQ(write_scene(second), written);
  ASSERT_EQ(second.protocol.size(), first.protocol.size());
  for (size_t i = 0; i < first.protocol.size(); ++i) {
    EXPECT_EQ(second.protocol[i].kind(), first.protocol[i].kind());
    EXPECT_EQ(second.protocol[i].pointer, first.protocol[i].pointer);
  }
  EXPECT_EQ(second.grid.width, first.grid.width);
  EXPECT_EQ(second.sheet.material.youngs_modulus, first.sheet.material.youngs_modulus);
  const PreparedScene a = prepare_scene(first), b = prepare_scene(second);
  EXPECT_EQ(a.membrane.sheet.model.num_particles(), b.membrane.sheet.model.num_particles());
  EXPECT_EQ(a.membrane.sheet.model.springs.rest_length, b.membrane.sheet.model.springs.rest_length);
  EXPECT_EQ(a.pinned, b.pinned);
  EXPECT_EQ(a.force_scale, b.force_scale);
}

INSTANTIATE_TEST_SUITE_P(Examples, RoundTrip, ::testing::ValuesIn(example_scenes()),
                         [](const auto& test) { return fs::path(test.param).stem().string(); });

TEST(SceneWriter, AWrittenSceneRunsToTheSameForm) {
  // exp7 has a cut and a hole, exp4 a grow field: on a small grid, bit for bit.
  for (const char* name : {"exp7_cut.json", "exp4_intrinsic_sin2.json"}) {
    const Scene original = load_scene(
        kWriterExamples / name, {"sheet.resolution=[11,11]", "simulation.max_iterations=3000"});
    const Scene written = parse_scene(write_scene(original), kWriterExamples);
    const RunResult a = run_scene(original), b = run_scene(written);
    EXPECT_EQ(a.prepared.membrane.state.x, b.prepared.membrane.state.x) << name;
    EXPECT_EQ(a.solve.iterations, b.solve.iterations) << name;
  }
}

TEST(SceneWriter, ARampIsWrittenAndReadBack) {
  // No example ramps, so the round trip above never sees the field.
  const json j = {
      {"name", "r"},
      {"sheet", {{"size", {100, 100}}, {"resolution", {5, 5}}}},
      {"simulation", {{"solver", "rk4"}, {"T", 4e-6}, {"steps", 25000}, {"ramp_seconds", 0.1}}},
      {"protocol", {{{"step", "stretch"}, {"lambda", {1.2, 1.2}}}}}};
  const Scene first = parse_scene(j);  // 25000 x 4e-6 rounds just below 0.1: still accepted
  const json w = write_scene(first);
  EXPECT_EQ(w["simulation"]["ramp_seconds"], 0.1);
  EXPECT_DOUBLE_EQ(parse_scene(w).simulation.ramp_seconds, 0.1);
}

TEST(SceneWriter, SelfContactIsWrittenAndReadBack) {
  // No example asks for self-contact, so the round trip above never sees the field.
  json j = {{"name", "c"},
            {"model", "continuum"},
            {"sheet", {{"size", {100, 100}}}},
            {"simulation", {{"self_contact", {{"gap", 0.5}, {"pressure", 3.0}}}}},
            {"protocol", {{{"step", "stretch"}, {"lambda", {1.2, 1.2}}}}}};
  const SelfContactSpec back = parse_scene(write_scene(parse_scene(j))).simulation.self_contact;
  EXPECT_TRUE(back.on);
  EXPECT_DOUBLE_EQ(back.gap, 5e-4);
  EXPECT_DOUBLE_EQ(back.pressure, 3000.0);
  EXPECT_DOUBLE_EQ(back.exclusion, 1.5e-3);
  json off = j;
  off["simulation"].erase("self_contact");
  EXPECT_FALSE(write_scene(parse_scene(off))["simulation"].contains("self_contact"));
}

TEST(SceneWriter, CustomMaterialsAreWrittenAndPresetsNamed) {
  json j = {{"name", "m"},
            {"materials", {{"soft", {{"E", 0.7}, {"thickness", 0.3}, {"density", 1.0}}}}},
            {"sheet", {{"size", {100, 100}}, {"resolution", {5, 5}}, {"material", "soft"}}},
            {"simulation", {{"G", 0}}},
            {"protocol",
             {{{"step", "stretch"}, {"lambda", {1.2, 1.2}}},
              {{"step", "impregnate"},
               {"pattern", {{"circle", {{"center", {60, 60}}, {"radius", 20}}}}}}}}};
  const json w = write_scene(parse_scene(j));
  EXPECT_EQ(w["materials"]["soft"]["E"], 0.7);
  EXPECT_EQ(w["materials"]["soft"]["thickness"], 0.3);
  EXPECT_FALSE(w["materials"].contains("epoxy"));  // the preset, as it stands: its name is enough
  EXPECT_EQ(w["protocol"][1]["material"], "epoxy");
  EXPECT_EQ(w["protocol"][1]["pattern"]["circle"]["radius"], 20.0);
}

// A continuum scene's law and wrinkling are written and read back; the lattice has no use for
// either, so they stay out of its files.
TEST(SceneWriter, TheContinuumsLawAndWrinklingAreWrittenAndReadBack) {
  json j = {{"name", "w"},
            {"model", "continuum"},
            {"materials", {{"latex", {{"law", "mooney_rivlin"}, {"wrinkling", "relaxed"}}}}},
            {"sheet", {{"size", {100, 100}}, {"material", "latex"}}},
            {"protocol", {{{"step", "stretch"}, {"lambda", {1.2, 1.2}}}}}};
  const Scene first = parse_scene(j);
  const json w = write_scene(first);
  EXPECT_EQ(w["materials"]["latex"]["wrinkling"], "relaxed");
  EXPECT_EQ(w["materials"]["latex"]["law"], "mooney_rivlin");
  const Scene again = parse_scene(w);
  EXPECT_EQ(again.sheet.material.wrinkling, Wrinkling::relaxed);
  EXPECT_EQ(again.sheet.material.law, MembraneLaw::mooney_rivlin);
  // Wrinkling alone makes the latex differ from its preset, so it is written.
  j["materials"]["latex"].erase("law");
  const json only = write_scene(parse_scene(j));
  EXPECT_EQ(only["materials"]["latex"]["wrinkling"], "relaxed");
  EXPECT_EQ(parse_scene(only).sheet.material.wrinkling, Wrinkling::relaxed);
  // The lattice ignores both, and its files leave them out.
  j["model"] = "lattice";
  j["sheet"]["resolution"] = {5, 5};
  const json lattice = write_scene(parse_scene(j));
  EXPECT_FALSE(lattice["materials"]["latex"].contains("wrinkling"));
}

}  // namespace
}  // namespace membra
