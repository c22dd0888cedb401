// libFuzzer target: any bytes as a grey PNG mask or field.
#include <cstddef>
#include <cstdint>

#include "membra/core/input_error.hpp"
#include "membra/io/image.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const membra::GreyImage img = membra::decode_grey_image(data, size, "fuzz.png", "/image");
    if (img.value.size() != static_cast<std::size_t>(img.width) * img.height) __builtin_trap();
  } catch (const membra::InputError&) {
  }
  return 0;
}
