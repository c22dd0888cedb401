#pragma once
// Scalar fields over the paper sheet from scene JSON (docs/scene.md, "Fields"): a number, a
// formula string, a grey image with a value range, or a named preset.
#include <filesystem>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "membra/core/vec.hpp"
#include "membra/model/formula.hpp"

namespace membra {

using ScalarField = std::function<double(const Vec2&)>;  // at a paper position, m

// Parses the field at `pointer`; images are relative to `base_dir`. Throws InputError naming the
// pointer for a formula that does not parse, an unreadable image, an unknown preset...
ScalarField read_field(const nlohmann::json& j, const std::string& pointer,
                       const std::filesystem::path& base_dir, const FormulaContext& context);

// The formula a preset stands for (with `a` its amplitude), or "" if there is no such preset.
std::string field_preset(const std::string& name);

}  // namespace membra
