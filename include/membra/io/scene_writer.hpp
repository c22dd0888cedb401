#pragma once
// Scene files written from the typed scene (process/scene.hpp): the inverse of io/scene.hpp's
// reader, so that what the viewer saves and what a design produces are ordinary scene files.
// Values go back to the scene's units (mm, MPa, g/cm^3, degrees); reading the written file gives
// the same typed scene up to round-off in the last digit of the unit conversions.
#include <nlohmann/json.hpp>

#include "membra/model/field_spec.hpp"
#include "membra/model/pattern_spec.hpp"
#include "membra/process/scene.hpp"

namespace membra {

// The whole scene, every value written out (defaults included).
nlohmann::json write_scene(const Scene& scene);

// One protocol step, as an element of "protocol".
nlohmann::json write_step(const ProtocolStep& step);

// A pattern (mm, degrees) and a field, as scenes write them.
nlohmann::json write_pattern(const PatternSpec& spec);
nlohmann::json write_field(const FieldSpec& spec);

}  // namespace membra
