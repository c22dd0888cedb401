// docs/scene.schema.json and the parser agree on every key, and the bundled examples are valid.
#include <filesystem>
#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "membra/io/design_reader.hpp"
#include "membra/io/pattern_reader.hpp"
#include "membra/io/scene.hpp"
#include "membra/process/run.hpp"

namespace membra {
namespace {

using nlohmann::json;

json load_json(const std::filesystem::path& p) {
  std::ifstream in(p);
  return json::parse(in);
}

// The schema object describing the value at a key pattern such as "/pins/*".
const json& schema_at(const json& schema, const std::string& pattern) {
  const json* node = &schema;
  size_t start = 1;
  while (start <= pattern.size() && !pattern.empty()) {
    const size_t slash = std::min(pattern.find('/', start), pattern.size());
    const std::string part = pattern.substr(start, slash - start);
    if (part == "*") {
      node = node->contains("items") ? &(*node)["items"] : &(*node)["additionalProperties"];
    } else if (part[0] == '*') {  // "*kind": the oneOf item whose "step" is kind
      const json* items = &(*node)["items"]["oneOf"];
      for (const auto& alt : *items)
        if (alt["properties"]["step"]["const"] == part.substr(1)) node = &alt;
    } else
      node = &(*node)["properties"][part];
    start = slash + 1;
  }
  return *node;
}

TEST(Schema, KeysMatchTheParser) {
  const json schema =
      load_json(std::filesystem::path(MEMBRA_SOURCE_DIR) / "docs/scene.schema.json");
  for (const auto& [pattern, keys] : scene_known_keys()) {
    const json& node = schema_at(schema, pattern);
    ASSERT_TRUE(node.contains("properties")) << pattern;
    std::set<std::string> in_schema;
    for (const auto& [k, v] : node["properties"].items()) in_schema.insert(k);
    EXPECT_EQ(in_schema, std::set<std::string>(keys.begin(), keys.end())) << pattern;
    EXPECT_EQ(node.value("additionalProperties", true), false) << pattern;
  }
}

TEST(Schema, PatternKeysMatchTheParser) {
  const json schema =
      load_json(std::filesystem::path(MEMBRA_SOURCE_DIR) / "docs/scene.schema.json");
  const json& pattern = schema["$defs"]["pattern"];
  for (const auto& [kind, keys] : pattern_known_keys()) {
    const json& node = kind.empty() ? pattern : pattern["properties"][kind];
    std::set<std::string> in_schema;
    for (const auto& [k, v] : node["properties"].items()) in_schema.insert(k);
    EXPECT_EQ(in_schema, std::set<std::string>(keys.begin(), keys.end())) << kind;
  }
}

TEST(Schema, EveryExampleSceneAndDesignIsValid) {
  int scenes = 0, designs = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::filesystem::path(MEMBRA_SOURCE_DIR) / "examples")) {
    if (entry.path().extension() != ".json") continue;
    // inverse_*.json are design files for `membra design target` (docs/inverse_design.md).
    if (entry.path().filename().string().starts_with("inverse_")) {
      ++designs;
      EXPECT_NO_THROW(load_design(entry.path())) << entry.path();
    } else {
      ++scenes;
      EXPECT_NO_THROW(prepare_scene(load_scene(entry.path()))) << entry.path();
    }
  }
  EXPECT_GE(scenes, 1);
  EXPECT_EQ(designs, 6);
}

// The benchmark scenes (bench/scenes) are read as written; meshing the 1 m panel takes 20 s and
// is left to its benchmark run (docs/performance.md, "A 1 m panel").
TEST(Schema, EveryBenchmarkSceneReads) {
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(
           std::filesystem::path(MEMBRA_SOURCE_DIR) / "bench" / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    ++scenes;
    EXPECT_NO_THROW(load_scene(entry.path())) << entry.path();
  }
  EXPECT_GE(scenes, 1);
}

}  // namespace
}  // namespace membra
