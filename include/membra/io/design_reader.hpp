#pragma once
// Design files (`membra design target FILE`, docs/inverse_design.md): read into the typed design
// of design/inverse_design.hpp, and the scene file of a designed stencil.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "membra/design/inverse_design.hpp"

namespace membra {

// Reads a design file. Throws InputError naming the file and field.
DesignSpec load_design(const std::filesystem::path& file);
DesignSpec parse_design(const nlohmann::json& j, const std::filesystem::path& base_dir = ".");

// The scene file that simulates a stencil for a design (sheet, stretch, impregnate, release):
// what `membra run` reproduces the design's form from.
nlohmann::json design_scene(const DesignSpec& spec, const Stencil& stencil);

}  // namespace membra
