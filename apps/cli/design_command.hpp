#pragma once
// `membra design target FILE --out DIR`: inverse design from a target surface.
#include <string>

namespace membra::cli {

struct DesignArgs {
  std::string file;
  std::string out_dir;  // default out/<name>
  bool quiet = false;
  bool no_cache = false;  // measure the stencil calibration even if a stored one fits
};

// Returns the exit code: 0, or 5 when the target cannot be reached (the best attempt is still
// written). Throws InputError for a bad design file.
int cmd_design(const DesignArgs& args);

}  // namespace membra::cli
