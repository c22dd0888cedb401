#include "membra/output/calibration_store.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <unistd.h>
#include <nlohmann/json.hpp>

#include "membra/design/stencil_layout.hpp"
#include "membra/design/stencil_trial.hpp"
#include "membra/io/scene_writer.hpp"
#include "membra/version.hpp"

namespace membra {
namespace fs = std::filesystem;
namespace {

// FNV-1a: a stable 64-bit hash for the file name (the full key inside the file decides).
std::string hex_hash(const std::string& text) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  std::ostringstream out;
  out << std::hex << h;
  return out.str();
}

fs::path file_for(const fs::path& dir, const std::string& key) {
  return dir / ("calibration-" + hex_hash(key) + ".json");
}

bool finite_rising(const std::vector<double>& v) {
  for (size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]) || (i > 0 && v[i] < v[i - 1])) return false;
  return v.size() >= 2;
}

std::optional<StencilCalibration> load(const fs::path& dir, const DesignSpec& spec, int samples) {
  const std::string key = calibration_key(spec, samples);
  std::ifstream in(file_for(dir, key));
  if (!in) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    if (j.at("key").get<std::string>() != key) return std::nullopt;
    StencilCalibration c;
    c.share = j.at("share").get<std::vector<double>>();
    c.density = j.at("density").get<std::vector<double>>();
    c.measured = j.at("measured").get<std::vector<double>>();
    c.min_share = j.at("min_share").get<double>();
    c.max_share = j.at("max_share").get<double>();
    if (c.share.size() != c.density.size() || !finite_rising(c.share) ||
        !finite_rising(c.density) || !(c.min_share > 0.0 && c.min_share < c.max_share))
      return std::nullopt;
    return c;
  } catch (const std::exception&) {
    return std::nullopt;  // damaged: measured again and replaced
  }
}

// Written to a temporary name and renamed, so that a reader never sees half a file.
void store(const fs::path& dir, const DesignSpec& spec, int samples, const StencilCalibration& c) {
  const std::string key = calibration_key(spec, samples);
  const nlohmann::json j = {{"key", key},
                            {"share", c.share},
                            {"density", c.density},
                            {"measured", c.measured},
                            {"min_share", c.min_share},
                            {"max_share", c.max_share}};
  std::error_code ec;
  fs::create_directories(dir, ec);
  const fs::path final_path = file_for(dir, key);
  const fs::path tmp = final_path.string() + ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(tmp);
    out << j.dump(1) << '\n';
    if (!out.flush()) {
      fs::remove(tmp, ec);
      return;
    }
  }
  fs::rename(tmp, final_path, ec);
  if (ec) fs::remove(tmp, ec);
}

}  // namespace

fs::path default_cache_dir() {
  const char* own = std::getenv("MEMBRA_CACHE_DIR");
  if (own && *own) return std::string(own) == "off" ? fs::path() : fs::path(own);
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "membra";
  if (const char* home = std::getenv("HOME"); home && *home)
    return fs::path(home) / ".cache" / "membra";
  return {};
}

std::string calibration_key(const DesignSpec& spec, int samples) {
  // The scene as the calibration releases it, with the middle sample's stencil (squares of side
  // half a cell: written out, the resin and its face come with it), named neutrally so that
  // designs on the same sheet share it.
  const Stencil middle = layout_stencil([](const Vec2&) { return 0.25; },
                                        {Vec2::Zero(), Vec2(spec.frame, spec.frame)}, spec.layout);
  Scene scene = stencil_scene(spec, middle);
  scene.simulation.solver = Solver::newton;
  scene.name = "calibration";
  scene.description.clear();
  scene.file.clear();
  const nlohmann::json key = {{"membra", kVersion},
                              {"scene", write_scene(scene)},
                              {"frame", spec.frame},
                              {"cell", spec.layout.cell},
                              {"min_feature", spec.layout.min_feature},
                              {"samples", samples}};
  return key.dump();
}

std::shared_ptr<const CalibrationCache> calibration_store(const fs::path& dir) {
  auto cache = std::make_shared<CalibrationCache>();
  cache->load = [dir](const DesignSpec& spec, int samples) { return load(dir, spec, samples); };
  cache->store = [dir](const DesignSpec& spec, int samples, const StencilCalibration& c) {
    store(dir, spec, samples, c);
  };
  return cache;
}

}  // namespace membra
