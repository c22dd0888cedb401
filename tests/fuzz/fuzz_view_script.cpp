// libFuzzer target: any bytes as a viewer script (membra view SCENE --script FILE). A script
// either parses or is refused with an InputError naming the line; anything else is a bug.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "membra/core/input_error.hpp"
#include "membra/view/view_script.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    // Every accepted numeric argument reads back as a number, as the session will read it.
    for (const auto& c : membra::parse_view_script(in, "fuzz.txt"))
      for (size_t i = 0; i < c.words.size(); ++i) {
        try {
          (void)c.number(i);
        } catch (const std::exception&) {  // a word argument (a path, a mode), not a number
        }
      }
  } catch (const membra::InputError&) {
  }
  return 0;
}
