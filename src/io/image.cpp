#include "membra/io/image.hpp"

#include <memory>

#include <stb_image.h>

#include "membra/io/input_error.hpp"

namespace membra {

GreyImage load_grey_image(const std::filesystem::path& file, const std::string& where) {
  int w = 0, h = 0, channels = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> data(stbi_load(file.c_str(), &w, &h, &channels, 0),
                                                 stbi_image_free);
  if (!data)
    throw InputError(where, "cannot read image " + file.string() + ": " +
                                (stbi_failure_reason() ? stbi_failure_reason() : "unknown error"));
  GreyImage img{w, h, std::vector<float>(static_cast<size_t>(w) * h)};
  for (size_t i = 0; i < img.value.size(); ++i) {
    const stbi_uc* px = data.get() + i * channels;
    if (channels >= 3 && (px[0] != px[1] || px[1] != px[2]))
      throw InputError(where, "image " + file.string() + " is not grayscale (pixel " +
                                  std::to_string(i % w) + ", " + std::to_string(i / w) +
                                  " has colour); save it as a grey PNG");
    img.value[i] = static_cast<float>(px[0]) / 255.0f;
  }
  return img;
}

}  // namespace membra
