#pragma once
// Patterns from scene JSON (docs/scene.md, "Patterns"). Values in mm and degrees; the pattern
// is built in SI frame coordinates.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "membra/io/json_reader.hpp"
#include "membra/model/pattern.hpp"
#include "membra/model/pattern_spec.hpp"

namespace membra {

// Parses the pattern at `pointer` into its description (images loaded). Image paths are relative
// to `base_dir`. Throws InputError naming the JSON pointer of a bad value.
PatternSpec read_pattern_spec(const nlohmann::json& j, const std::string& pointer,
                              const std::filesystem::path& base_dir);

// The array of [x, y] points (mm) at `key`, at least `min_count`, in m. Throws InputError
// naming the JSON pointer of a bad value.
std::vector<Vec2> read_points(const JsonObject& o, std::string_view key, size_t min_count);

// Keys of each pattern kind, for the schema test.
std::map<std::string, std::vector<std::string>> pattern_known_keys();

}  // namespace membra
