#pragma once
// Reading grey images (PNG masks and fields) and writing PNG pictures.
#include <filesystem>
#include <string>
#include <vector>

#include "membra/core/grey_image.hpp"

namespace membra {

// Reads a PNG (or any format stb_image reads) as grey. An RGB(A) image is accepted only if every
// pixel has R = G = B. Throws InputError at `where` if the file cannot be read or has colour.
GreyImage load_grey_image(const std::filesystem::path& file, const std::string& where);

// The same from the bytes of a file called `name` (for messages). Images of more than
// kMaxImagePixels are refused from their header, before decoding.
constexpr double kMaxImagePixels = 64.0 * 1024 * 1024;
GreyImage decode_grey_image(const unsigned char* bytes, size_t size, const std::string& name,
                            const std::string& where);

}  // namespace membra
