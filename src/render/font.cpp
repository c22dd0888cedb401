#include "membra/render/font.hpp"

#include <stb_truetype.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include "membra/render/renderer.hpp"

#ifndef MEMBRA_FONT_FILE
#define MEMBRA_FONT_FILE "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
#endif

namespace membra {

std::vector<char32_t> decode_utf8(const std::string& s) {
  std::vector<char32_t> out;
  for (size_t i = 0; i < s.size();) {
    const auto b = static_cast<unsigned char>(s[i]);
    const int extra = b < 0x80         ? 0
                      : (b >> 5) == 6  ? 1
                      : (b >> 4) == 14 ? 2
                      : (b >> 3) == 30 ? 3
                                       : -1;
    if (extra < 0 || i + static_cast<size_t>(extra) >= s.size()) {
      out.push_back(0xFFFD);
      ++i;
      continue;
    }
    char32_t c = extra == 0 ? b : b & (0x3F >> extra);
    bool ok = true;
    for (int k = 1; k <= extra; ++k) {
      const auto n = static_cast<unsigned char>(s[i + static_cast<size_t>(k)]);
      ok = ok && (n >> 6) == 2;
      c = (c << 6) | (n & 0x3F);
    }
    // Overlong forms, surrogates and code points beyond U+10FFFF are not text.
    static constexpr char32_t kLeast[] = {0, 0x80, 0x800, 0x10000};
    ok = ok && c >= kLeast[extra] && c <= 0x10FFFF && (c < 0xD800 || c > 0xDFFF);
    out.push_back(ok ? c : 0xFFFD);
    i += ok ? static_cast<size_t>(extra) + 1 : 1;
  }
  return out;
}

struct Font::Impl {
  std::vector<unsigned char> data;
  stbtt_fontinfo info{};
};

Font::Font(const std::filesystem::path& ttf) : impl_(std::make_unique<Impl>()) {
  std::ifstream in(ttf, std::ios::binary);
  if (!in)
    throw RenderError(ttf.string() +
                      ": cannot read the font (install fonts-dejavu-core "
                      "or set MEMBRA_FONT to a .ttf file)");
  impl_->data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  // stb_truetype trusts its input: check the header and that the table directory lies inside
  // the file before handing it over (an empty file, a .woff, a truncated download).
  const auto& d = impl_->data;
  const auto u32 = [&](size_t at) {
    return (std::uint32_t(d[at]) << 24) | (std::uint32_t(d[at + 1]) << 16) |
           (std::uint32_t(d[at + 2]) << 8) | std::uint32_t(d[at + 3]);
  };
  const bool header = d.size() >= 12 && (u32(0) == 0x00010000u || u32(0) == 0x74727565u);
  const size_t tables = header ? (std::uint32_t(d[4]) << 8 | d[5]) : 0;
  bool inside = header && 12 + 16 * tables <= d.size();
  for (size_t t = 0; inside && t < tables; ++t) {
    const size_t entry = 12 + 16 * t;
    inside = std::uint64_t(u32(entry + 8)) + u32(entry + 12) <= d.size();
  }
  if (!inside || !stbtt_InitFont(&impl_->info, impl_->data.data(), 0))
    throw RenderError(ttf.string() + ": not a TrueType font (or a truncated one)");
}

Font::~Font() = default;

const Font& Font::standard() {
  static const Font font([] {
    const char* env = std::getenv("MEMBRA_FONT");
    return std::filesystem::path(env && *env ? env : MEMBRA_FONT_FILE);
  }());
  return font;
}

float Font::width(const std::string& utf8, float px) const {
  const stbtt_fontinfo& f = impl_->info;
  const float scale = stbtt_ScaleForPixelHeight(&f, px);
  const auto cps = decode_utf8(utf8);
  float w = 0.0f;
  for (size_t i = 0; i < cps.size(); ++i) {
    int advance = 0, lsb = 0;
    stbtt_GetCodepointHMetrics(&f, static_cast<int>(cps[i]), &advance, &lsb);
    w += scale * static_cast<float>(advance);
    if (i + 1 < cps.size())
      w += scale * static_cast<float>(stbtt_GetCodepointKernAdvance(&f, static_cast<int>(cps[i]),
                                                                    static_cast<int>(cps[i + 1])));
  }
  return w;
}

TextBitmap Font::rasterize(const std::string& utf8, float px) const {
  const stbtt_fontinfo& f = impl_->info;
  const float scale = stbtt_ScaleForPixelHeight(&f, px);
  int ascent = 0, descent = 0, gap = 0;
  stbtt_GetFontVMetrics(&f, &ascent, &descent, &gap);
  TextBitmap t;
  t.ascent = 1 + static_cast<int>(std::ceil(scale * static_cast<float>(ascent)));
  t.width = static_cast<int>(std::ceil(width(utf8, px))) + 3;
  t.height = t.ascent + static_cast<int>(std::ceil(-scale * static_cast<float>(descent))) + 2;
  t.coverage.assign(static_cast<size_t>(t.width) * static_cast<size_t>(t.height), 0);
  const auto cps = decode_utf8(utf8);
  float pen = 1.0f;
  std::vector<unsigned char> glyph;
  for (size_t i = 0; i < cps.size(); ++i) {
    const int cp = static_cast<int>(cps[i]);
    const float shift = pen - std::floor(pen);
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    stbtt_GetCodepointBitmapBoxSubpixel(&f, cp, scale, scale, shift, 0.0f, &x0, &y0, &x1, &y1);
    const int gw = x1 - x0, gh = y1 - y0;
    if (gw > 0 && gh > 0) {
      glyph.assign(static_cast<size_t>(gw) * static_cast<size_t>(gh), 0);
      stbtt_MakeCodepointBitmapSubpixel(&f, glyph.data(), gw, gh, gw, scale, scale, shift, 0.0f,
                                        cp);
      const int ox = static_cast<int>(std::floor(pen)) + x0, oy = t.ascent + y0;
      for (int y = 0; y < gh; ++y)
        for (int x = 0; x < gw; ++x) {
          const int tx = ox + x, ty = oy + y;
          if (tx < 0 || ty < 0 || tx >= t.width || ty >= t.height) continue;
          auto& dst = t.coverage[static_cast<size_t>(ty) * static_cast<size_t>(t.width) +
                                 static_cast<size_t>(tx)];
          dst = std::max(
              dst,
              glyph[static_cast<size_t>(y) * static_cast<size_t>(gw) + static_cast<size_t>(x)]);
        }
    }
    int advance = 0, lsb = 0;
    stbtt_GetCodepointHMetrics(&f, cp, &advance, &lsb);
    pen += scale * static_cast<float>(advance);
    if (i + 1 < cps.size())
      pen += scale * static_cast<float>(
                         stbtt_GetCodepointKernAdvance(&f, cp, static_cast<int>(cps[i + 1])));
  }
  return t;
}

}  // namespace membra
