// Scenes: JSON text in, a typed and validated Scene out (the same reader as `membra run`).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <nlohmann/json.hpp>

#include "bindings.hpp"
#include "membra/core/input_error.hpp"
#include "membra/io/scene.hpp"
#include "membra/process/prepare.hpp"

namespace membra::python {

namespace {

// Parses JSON text, naming `where` (a file or "scene") in the message of malformed text.
nlohmann::json parse_json_text(const std::string& text, const std::string& where) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(where, std::string("malformed JSON: ") + e.what());
  }
}

// What prepare_scene builds, for Scene.validate(): the counts `membra validate` prints.
py::dict validate(const ScenePtr& scene) {
  const PreparedScene p = prepare_scene(*scene);
  py::dict d;
  d["particles"] = p.membrane.sheet.model.num_particles();
  d["springs"] = p.membrane.sheet.model.springs.size();
  d["pinned"] = p.pinned;
  return d;
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<Scene, ScenePtr>(m, "NativeScene")
      .def_property_readonly("name", [](const Scene& s) { return s.name; })
      .def_property_readonly("steps", [](const Scene& s) { return s.protocol.size(); });
  m.def(
      "parse_scene",
      [](const std::string& text, const std::filesystem::path& base_dir) {
        return std::make_shared<Scene>(parse_scene(parse_json_text(text, "scene"), base_dir));
      },
      py::arg("text"), py::arg("base_dir"));
  m.def(
      "load_scene",
      [](const std::filesystem::path& file, const std::vector<std::string>& sets) {
        return std::make_shared<Scene>(load_scene(file, sets));
      },
      py::arg("file"), py::arg("sets"));
  m.def(
      "apply_overrides",
      [](const std::string& text, const std::vector<std::string>& sets) {
        nlohmann::json j = parse_json_text(text, "scene");
        for (const std::string& s : sets) apply_override(j, s);
        return j.dump();
      },
      py::arg("text"), py::arg("sets"));
  m.def("validate", &validate, py::arg("scene"));
}

}  // namespace membra::python
