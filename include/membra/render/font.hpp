#pragma once
// Text set in a TrueType font (DejaVu Sans, Debian's fonts-dejavu-core) through stb_truetype:
// antialiased coverage bitmaps that the painter draws as textures, so that the pictures' titles
// and legends read like text, not like a bitmap font.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace membra {

// A line of text as coverage (0 transparent .. 255 ink), rows from the top; the baseline lies
// `ascent` pixels below the top row.
struct TextBitmap {
  int width = 0, height = 0, ascent = 0;
  std::vector<std::uint8_t> coverage;
};

class Font {
 public:
  // Reads a TrueType file; throws RenderError naming it when it cannot be read or parsed.
  explicit Font(const std::filesystem::path& ttf);
  ~Font();
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  // The pictures' font: $MEMBRA_FONT when set, else DejaVu Sans where Debian installs it
  // (the compiled-in MEMBRA_FONT_FILE). Loaded once; throws RenderError when missing.
  static const Font& standard();

  // Width in pixels of a UTF-8 line set `pixel_height` pixels high (ascent to descent).
  float width(const std::string& utf8, float pixel_height) const;
  // The line rasterized with its kerning, `pixel_height` high plus a pixel of padding all round.
  TextBitmap rasterize(const std::string& utf8, float pixel_height) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The code points of a UTF-8 string (invalid bytes become U+FFFD).
std::vector<char32_t> decode_utf8(const std::string& utf8);

}  // namespace membra
