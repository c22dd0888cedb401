// libFuzzer target: any bytes as the pattern of an impregnate step on the continuum model, the
// sheet meshed along its outlines (docs/model.md, "Meshes that follow the pattern") and the step
// applied (which counts the triangles across the outline). A pattern either meshes and impregnates
// or is refused with an InputError; anything else (a crash, a sanitizer report, another
// exception, a hang) is a bug. The mesh is kept small (a 30 x 20 mm sheet, one element across a
// feature, 0.2 mm chords: features under 2 mm are refused), so that no input meshes for long.
#include <cstddef>
#include <cstdint>
#include <string>

#include "membra/core/input_error.hpp"
#include "membra/io/scene.hpp"
#include "membra/process/run.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const nlohmann::json pattern = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (pattern.is_discarded()) return 0;
  nlohmann::json scene = nlohmann::json::parse(R"({"name": "fuzz_mesh", "model": "continuum",
    "sheet": {"size": [30, 20], "material": "latex",
              "mesh": {"max_edge": 5, "elements_across": 1, "tolerance": 0.2}},
    "protocol": [{"step": "stretch", "lambda": [1.5, 1.0]},
                 {"step": "impregnate", "material": "epoxy"}]})");
  scene["protocol"][1]["pattern"] = pattern;
  try {
    const membra::Scene s = membra::parse_scene(scene, "/nonexistent");
    membra::SceneRun run(s);
    for (const membra::ProtocolStep& step : s.protocol) (void)run.apply(step);
  } catch (const membra::InputError&) {
  }
  return 0;
}
