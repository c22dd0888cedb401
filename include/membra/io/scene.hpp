#pragma once
// Scene files: the JSON that describes one reproducible membra run, read into the typed scene of
// process/scene.hpp and fully validated here; values are converted from the scene's units (mm,
// MPa, g/cm^3, s, N) to SI. The format is documented in docs/scene.md and docs/scene.schema.json.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "membra/core/input_error.hpp"
#include "membra/process/scene.hpp"

namespace membra {

// Parses and validates a scene; files it names (images) are relative to base_dir. Throws
// InputError naming the JSON pointer of the first problem.
Scene parse_scene(const nlohmann::json& j, const std::filesystem::path& base_dir = ".");
// Reads a scene file, applying `overrides` (see apply_override) before validation. Throws
// InputError whose message starts with the file name: unreadable file, malformed JSON (with line
// and column), a bad override, or any invalid field.
Scene load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

// Applies one "dotted.path=value" assignment to a scene's JSON, e.g. "simulation.steps=500" or
// "sheet.resolution=[21,21]". The value is read as JSON, or taken as a string if it is not JSON.
// Array elements are addressed by index ("sheet.size.0=150"). Throws InputError for a malformed
// assignment.
void apply_override(nlohmann::json& scene, const std::string& assignment);

// Keys the parser accepts in each object, by JSON pointer pattern ("/sheet", "/pins/*"), so that
// docs/scene.schema.json can be checked against the code.
std::map<std::string, std::vector<std::string>> scene_known_keys();

}  // namespace membra
