#pragma once
// The protocol of a scene file (docs/scene.md, "Protocol"): one reader per step kind, each into
// its typed step (process/protocol.hpp), checked in order, since the frame a pattern must fit
// depends on the stretches before it and a static solve of a free sheet under gravity has no
// equilibrium.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "membra/io/json_reader.hpp"
#include "membra/model/material.hpp"
#include "membra/process/scene.hpp"

namespace membra {

// Reads top["protocol"] into scene.protocol (the sheet, pins and simulation already read).
// Throws InputError naming the field.
// The error for a material that is neither defined under /materials nor a preset: it lists the
// known ones and suggests the nearest.
InputError unknown_material(const std::string& pointer, const std::string& name,
                            const std::map<std::string, Material>& materials);

void parse_protocol(const JsonObject& top, const std::map<std::string, Material>& materials,
                    const std::filesystem::path& base_dir, Scene& scene);

// Reads parent["pins"] (the scene's, or a load step's) into `pins`.
void parse_pins(const JsonObject& parent, const Scene& scene, std::vector<PinSpec>& pins);

// Keys each step kind accepts, by pointer pattern ("/protocol/*grow"), for the schema test.
std::map<std::string, std::vector<std::string>> protocol_known_keys();

}  // namespace membra
