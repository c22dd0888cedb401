#include "membra/io/image.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>

#include <stb_image.h>

#include "membra/core/input_error.hpp"

namespace membra {

GreyImage decode_grey_image(const unsigned char* bytes, size_t size, const std::string& name,
                            const std::string& where) {
  if (size > static_cast<size_t>(std::numeric_limits<int>::max()))
    throw InputError(where, "image " + name + " is too large a file");
  const int n = static_cast<int>(size);
  int w = 0, h = 0, channels = 0;
  // Check the header first: a few bytes can claim a picture of gigabytes.
  if (stbi_info_from_memory(bytes, n, &w, &h, &channels) &&
      static_cast<double>(w) * h > kMaxImagePixels)
    throw InputError(where, "image " + name + " has " + std::to_string(w) + " x " +
                                std::to_string(h) + " pixels; at most " +
                                std::to_string(static_cast<long>(kMaxImagePixels)) +
                                " are accepted");
  std::unique_ptr<stbi_uc, void (*)(void*)> data(
      stbi_load_from_memory(bytes, n, &w, &h, &channels, 0), stbi_image_free);
  if (!data)
    throw InputError(where, "cannot read image " + name + ": " +
                                (stbi_failure_reason() ? stbi_failure_reason() : "unknown error"));
  GreyImage img{w, h, std::vector<float>(static_cast<size_t>(w) * h)};
  for (size_t i = 0; i < img.value.size(); ++i) {
    const stbi_uc* px = data.get() + i * channels;
    if (channels >= 3 && (px[0] != px[1] || px[1] != px[2]))
      throw InputError(where, "image " + name + " is not grayscale (pixel " +
                                  std::to_string(i % w) + ", " + std::to_string(i / w) +
                                  " has colour); save it as a grey PNG");
    img.value[i] = static_cast<float>(px[0]) / 255.0f;
  }
  return img;
}

GreyImage load_grey_image(const std::filesystem::path& file, const std::string& where) {
  std::ifstream in(file, std::ios::binary);
  if (!std::filesystem::is_regular_file(file) || !in)  // not a device or pipe read without end
    throw InputError(where, "cannot read image " + file.string() + ": cannot open file");
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                std::istreambuf_iterator<char>());
  return decode_grey_image(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(),
                           file.string(), where);
}

}  // namespace membra
