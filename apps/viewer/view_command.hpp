#pragma once
// `membra view [SCENE] [--script FILE]`: the interactive viewer, or a script driving it.
#include <string>
#include <vector>

namespace membra::viewer {

struct ViewArgs {
  std::string scene;                 // empty: a 200 x 200 mm latex sheet, 41 x 41 particles
  std::string script;                // empty: interactive
  std::vector<std::string> sets;     // --set overrides, as for `membra run`
  std::vector<int> size{1280, 800};  // window, pixels
};

// Returns the process exit code (0 ok, 2 bad input, 6 no display/OpenGL); prints errors.
int run_view(const ViewArgs& args);

}  // namespace membra::viewer
