#pragma once
// Stencil calibrations (design/stencil_calibration.hpp) kept on disk between designs: one JSON
// file per calibration, named by a hash of everything it was measured on — the scene its uniform
// stencils are released in (sheet, material, resin, stretch, release path, tolerance), the frame,
// the layout, the number of samples and membra's version — and holding that description in full,
// so a file is used only for exactly the inputs it was measured on (docs/inverse_design.md).
// A cache never fails a design: an unreadable, foreign or damaged file is measured again and
// replaced, and a directory that cannot be written is skipped.
#include <filesystem>
#include <memory>
#include <string>

#include "membra/design/stencil_calibration.hpp"

namespace membra {

// $MEMBRA_CACHE_DIR, else $XDG_CACHE_HOME/membra, else $HOME/.cache/membra; empty when none is
// set or MEMBRA_CACHE_DIR is "off".
std::filesystem::path default_cache_dir();

// The canonical description of a calibration's inputs (compact JSON text).
std::string calibration_key(const DesignSpec& spec, int samples);

// A cache in `dir` (created when the first calibration is stored).
std::shared_ptr<const CalibrationCache> calibration_store(const std::filesystem::path& dir);

}  // namespace membra
