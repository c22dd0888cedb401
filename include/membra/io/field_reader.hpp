#pragma once
// Scalar fields over the paper sheet from scene JSON (docs/scene.md, "Fields"): a number, a
// formula string, a grey image with a value range, or a named preset.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "membra/core/vec.hpp"
#include "membra/model/field_spec.hpp"
#include "membra/model/formula.hpp"

namespace membra {

// Parses the field at `pointer` into its description (images loaded, relative to `base_dir`).
// Throws InputError naming the pointer for an unreadable image, an unknown preset...
FieldSpec read_field_spec(const nlohmann::json& j, const std::string& pointer,
                          const std::filesystem::path& base_dir);

// Builds the field of a description; a formula that does not parse throws InputError at
// `pointer`.
ScalarField build_field(const FieldSpec& spec, const std::string& pointer,
                        const FormulaContext& context);

}  // namespace membra
