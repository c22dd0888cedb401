// libFuzzer target: any bytes as a design file (membra design target). A design file either
// parses or is refused with an InputError; anything else is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "membra/core/input_error.hpp"
#include "membra/io/design_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return 0;
  try {
    (void)membra::parse_design(j, "/nonexistent");
  } catch (const membra::InputError&) {
  }
  return 0;
}
